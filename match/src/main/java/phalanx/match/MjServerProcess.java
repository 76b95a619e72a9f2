package phalanx.match;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * One rcssservermj (the MuJoCo server, docs/rcssservermj.md) on 127.0.0.1 and its own ports, headless, in
 * a working folder of its own (it writes console.log into its working directory). Found as users have it:
 * {@code $PHALANX_RCSSSERVERMJ}, else the project's {@code .venv/bin/rcssservermj} (scripts/setup.sh), else
 * {@code rcssservermj} on PATH.
 */
public final class MjServerProcess {
    /**
     * {@code realTime = false} lets the server run as fast as sync-mode agents answer. One server run plays one
     * {@code phase} (0 first half, 1 second half) and ends in GameOver (games/soccer/sim/soccer_referee.py);
     * {@code startTime}, when not NaN, is the play time it starts at (--time), which shortens the half.
     */
    public record Settings(int agentPort, int monitorPort, boolean sync, boolean realTime, int phase, double startTime) {
        public Settings {
            if (agentPort <= 0 || monitorPort <= 0 || agentPort == monitorPort)
                throw new IllegalArgumentException("agent and monitor ports must be two different positive ports");
            if (!sync && !realTime)
                throw new IllegalArgumentException("a server that is neither real-time nor agent-sync runs away from its agents");
            if (phase < 0 || phase > 1) throw new IllegalArgumentException("phase must be 0 or 1, got " + phase);
        }

        public Settings(int agentPort, int monitorPort, boolean sync, boolean realTime) {
            this(agentPort, monitorPort, sync, realTime, 0, Double.NaN);
        }
    }

    private final Settings settings;
    private final SessionProcess process;
    private final Path log;

    private MjServerProcess(Settings settings, SessionProcess process, Path log) {
        this.settings = settings;
        this.process = process;
        this.log = log;
    }

    /** The server executable: the environment variable, the project's venv under {@code projectRoot}, PATH. */
    public static Optional<Path> find(Map<String, String> env, Path projectRoot) {
        List<Path> candidates = new ArrayList<>();
        String set = env.get("PHALANX_RCSSSERVERMJ");
        if (set != null && !set.isBlank()) return Optional.of(Path.of(set)).filter(Files::isExecutable);
        candidates.add(projectRoot.resolve(".venv/bin/rcssservermj"));
        for (String dir : env.getOrDefault("PATH", "").split(":"))
            if (!dir.isEmpty()) candidates.add(Path.of(dir, "rcssservermj"));
        return candidates.stream().filter(Files::isExecutable).findFirst();
    }

    /** The command line: localhost only, no viewer (it needs a display). */
    public static List<String> command(Path executable, Settings s) {
        List<String> argv = new ArrayList<>(List.of(executable.toString(), "--host", "127.0.0.1",
                "--aport", Integer.toString(s.agentPort()), "--mport", Integer.toString(s.monitorPort()), "--no-render"));
        if (s.sync()) argv.add("--sync");
        argv.add(s.realTime() ? "--realtime" : "--no-realtime");
        if (s.phase() != 0) argv.addAll(List.of("--phase", Integer.toString(s.phase())));
        if (!Double.isNaN(s.startTime())) argv.addAll(List.of("--time", Double.toString(s.startTime())));
        return argv;
    }

    /** Starts the server in {@code dir} (output to dir/server.log). */
    public static MjServerProcess start(Path executable, Settings s, Path dir) throws IOException {
        if (!ServerProcess.portFree(s.agentPort())) throw new IOException("agent port " + s.agentPort() + " is in use");
        if (!ServerProcess.portFree(s.monitorPort())) throw new IOException("monitor port " + s.monitorPort() + " is in use");
        Files.createDirectories(dir);
        Path log = dir.resolve("server.log");
        return new MjServerProcess(s, SessionProcess.start(command(executable, s), dir, log, "rcssservermj"), log);
    }

    /**
     * Waits until the server logs "Starting server... DONE!": it listens before its simulation loop runs, and
     * an agent that connects in between can be dropped (seen on a first start, when Python compiles the package).
     */
    public boolean awaitReady(long timeoutMillis) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (System.nanoTime() < deadline) {
            if (Files.exists(log) && Files.readString(log).contains("Starting server... DONE!")) return true;
            if (!alive()) return false;
            Thread.sleep(100);
        }
        return false;
    }

    public Settings settings() { return settings; }
    public Path log() { return log; }
    public long pid() { return process.pid(); }
    public boolean alive() { return process.anyAlive(); }

    /** SIGINT (its handler shuts the simulation down), SIGKILL after 10 s. */
    public void stop() { process.stop("INT", 10_000); }
}

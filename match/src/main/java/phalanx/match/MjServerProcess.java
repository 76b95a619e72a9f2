package phalanx.match;

import phalanx.comm.wire.ServerConnection;
import phalanx.comm.wire.WireException;

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
    private volatile ServerConnection monitor;
    private volatile double simTime = -1;
    private volatile boolean monitorClosed;
    private volatile String notReady;
    private volatile java.util.function.Consumer<String> listener;

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
     * {@link #start} then {@link #awaitReady}, and once more in {@code dir/retry} when that start was not ready:
     * rcsssmj 0.2.1 sometimes fails a start (docs/rcssservermj.md), and a second start costs seconds.
     * {@code onStart} gets each started server at once (so that a Ctrl-C meanwhile can stop it), {@code onRetry}
     * hears why the first start failed. Throws with both reasons and the log when neither was ready.
     */
    public static MjServerProcess startReady(Path executable, Settings s, Path dir, long timeoutMillis,
                                             java.util.function.Consumer<MjServerProcess> onStart,
                                             java.util.function.Consumer<String> onRetry) throws IOException, InterruptedException {
        String first = null;
        for (int attempt = 1; attempt <= 2; attempt++) {
            MjServerProcess server = start(executable, s, attempt == 1 ? dir : dir.resolve("retry"));
            onStart.accept(server);
            if (server.awaitReady(timeoutMillis)) return server;
            String why = server.notReadyReason();
            server.stop();
            if (attempt == 2) {
                throw new IOException("rcssservermj did not start, twice (" + first + "; then " + why + "); log "
                        + server.log() + ": " + tail(server.log()));
            }
            first = why;
            onRetry.accept(why + "; log " + server.log() + ": " + tail(server.log()));
        }
        throw new AssertionError("unreachable");
    }

    private static String tail(Path log) {
        try {
            String t = Files.readString(log, java.nio.charset.StandardCharsets.ISO_8859_1);
            return t.isEmpty() ? "(empty)" : t.substring(Math.max(0, t.length() - 2000));
        } catch (IOException e) {
            return "(unreadable: " + e.getMessage() + ")";
        }
    }

    /**
     * Waits until the server logs "Starting server... DONE!", then opens this server's one monitor connection and
     * waits until the simulation has stepped (a monitor message with simulation time > 0). Three server quirks
     * (rcsssmj 0.2.1, docs/rcssservermj.md): it listens before its loop runs, and an agent that connects in between
     * is dropped; a first agent that joins before the first step crashes the simulation thread (sim/audio_engine.py:
     * AudioData starts with origins of shape (0, 3), which the first step replaces by (3, 0); seen in 1 of 3 starts);
     * and a monitor connection closed while the server runs can crash it too (its simulation thread sends to the
     * closed socket: OSError Bad file descriptor, seen in 1 of 7). So the monitor stays open until {@link #stop}:
     * use {@link #command} and {@link #onMonitorMessage} rather than a connection of your own.
     */
    public boolean awaitReady(long timeoutMillis) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (!(Files.exists(log) && Files.readString(log).contains("Starting server... DONE!"))) {
            if (!alive()) return notReady("it exited before 'Starting server... DONE!' (exit " + process.exitCode() + ")");
            if (System.nanoTime() > deadline) return notReady("no 'Starting server... DONE!' within " + timeoutMillis / 1000 + " s");
            Thread.sleep(100);
        }
        long left = Math.max(1, (deadline - System.nanoTime()) / 1_000_000L);
        try {
            monitor = ServerConnection.connect("127.0.0.1", settings.monitorPort(), left);
        } catch (WireException e) {
            return notReady("its monitor port: " + e.getMessage());
        }
        Thread drain = new Thread(this::drainMonitor, "rcssservermj-monitor");
        drain.setDaemon(true);
        drain.start();
        while (simTime <= 0) {
            if (!alive()) return notReady("it exited after 'Starting server... DONE!' (exit " + process.exitCode() + ")");
            if (monitorClosed) return notReady("it closed the monitor connection before its first step");
            if (System.nanoTime() > deadline) return notReady("no simulation step within " + timeoutMillis / 1000 + " s");
            Thread.sleep(20);
        }
        return true;
    }

    private boolean notReady(String why) {
        notReady = why;
        return false;
    }

    /** Why {@link #awaitReady} said no, or null. */
    public String notReadyReason() { return notReady; }

    /** Reads the monitor stream for the server's lifetime (an unread stream would block the server's sends). */
    private void drainMonitor() {
        try {
            while (true) {
                monitor.reader().next();
                String m = monitor.reader().text();
                double t = simulationTime(m);
                if (t > 0) simTime = t;
                java.util.function.Consumer<String> l = listener;
                if (l != null) l.accept(m);
            }
        } catch (IOException e) {
            monitorClosed = true;   // the server stopped
        }
    }

    /** Every monitor message from now on goes to {@code l}, on the monitor thread. */
    public void onMonitorMessage(java.util.function.Consumer<String> l) { listener = l; }

    /** Sends a monitor command such as {@code (kickOff Left)}; only after {@link #awaitReady}. */
    public synchronized void command(String c) throws IOException {
        if (monitor == null) throw new IOException("rcssservermj's monitor is not connected (call awaitReady first)");
        monitor.send(c);
    }

    /** The {@code ((gt 1 0)T)} simulation time of a monitor message, or -1. */
    static double simulationTime(String monitorMessage) {
        int at = monitorMessage.indexOf("(gt 1 0)");
        if (at < 0) return -1;
        int end = monitorMessage.indexOf(')', at + 8);
        try {
            return end < 0 ? -1 : Double.parseDouble(monitorMessage.substring(at + 8, end).trim());
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    public Settings settings() { return settings; }
    public Path log() { return log; }
    public long pid() { return process.pid(); }
    /** The server itself (setsid execs it in place) or anything it started still runs. */
    public boolean alive() { return process.exitCode() == null || process.anyAlive(); }

    /** SIGINT (its handler shuts the simulation down), SIGKILL after 10 s; then the monitor connection closes. */
    public void stop() {
        process.stop("INT", 10_000);
        if (monitor != null) monitor.close();
    }
}

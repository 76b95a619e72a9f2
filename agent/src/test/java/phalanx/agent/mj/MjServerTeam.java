package phalanx.agent.mj;

import phalanx.agent.PlayerOptions;
import phalanx.match.MjServerProcess;
import phalanx.match.ServerProcess;
import phalanx.model.field.MjField;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.BooleanSupplier;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The real-server tests' set-up: an rcssservermj of its own (agent port 5300-5349, monitor 50 above: clear of the
 * SimSpark games' ports, 3500-3799 and 4100-4101, beside it) and our 7 T1s in this process, each its MjRuntime to look
 * into. Skips (assumption) without rcssservermj (scripts/setup.sh installs it into .venv). Closing stops the server and
 * the players.
 */
final class MjServerTeam implements AutoCloseable {
    final MjServerProcess server;
    final List<MjRuntime> team = new ArrayList<>();
    final List<Future<MjPlayer.Outcome>> outcomes = new ArrayList<>();
    private final ExecutorService pool;
    /** agent/mj's log at INFO while the team plays (kicks, drops, the double-touch rule, the keeper's states). */
    private static final Logger MJ_LOG = Logger.getLogger("phalanx.agent.mj");
    private final List<String> log = Collections.synchronizedList(new ArrayList<>());
    private final Handler handler = new Handler() {
        @Override public void publish(LogRecord r) { log.add(r.getLoggerName().replace("phalanx.agent.mj.", "") + ": " + r.getMessage()); }
        @Override public void flush() { }
        @Override public void close() { }
    };
    private final Level level = MJ_LOG.getLevel();

    private MjServerTeam(MjServerProcess server, ExecutorService pool) {
        this.server = server;
        this.pool = pool;
        MJ_LOG.setLevel(Level.INFO);
        MJ_LOG.addHandler(handler);
    }

    /** Prints the players' log lines so far, but the team channel's. */
    void printLog() {
        synchronized (log) {
            log.stream().filter(l -> !l.contains("team channel") && !l.contains("round ") && !l.contains("in the game"))
                    .forEach(l -> System.out.println("  " + l));
        }
    }

    /** The server in {@code phase} (0 first half, 1 second) and the team connected, every player running 3 s. */
    static MjServerTeam start(Path tmp, String name, int phase) throws Exception {
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        assumeTrue(exe.isPresent(), "rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
        int port = ServerProcess.freePortPair(5300, 50, 50);
        MjServerProcess server = MjServerProcess.startReady(exe.get(), new MjServerProcess.Settings(port, port + 50, true, false, phase, Double.NaN),
                tmp, 90_000, started -> { }, why -> System.out.println("rcssservermj started again: " + why));
        MjField field = MjField.SSIM;
        MjServerTeam t = new MjServerTeam(server, Executors.newFixedThreadPool(field.players()));
        try {
            for (int n = 1; n <= field.players(); n++) {
                MjRuntime r = new MjRuntime(name, n, field);
                t.team.add(r);
                PlayerOptions o = PlayerOptions.parse("--port", String.valueOf(port), "--team", name, "--unum", String.valueOf(n), "--server", "mj");
                t.outcomes.add(t.pool.submit(() -> MjPlayer.play(o, r)));
            }
            t.waitFor(() -> t.team.stream().allMatch(r -> r.cycles() > 150), "all players running 3 s");
        } catch (Exception | Error e) {
            t.close();
            throw e;
        }
        return t;
    }

    /** Waits (polling every 50 ms) until {@code done}; fails when a player ends first, or after 10 minutes (a hang guard only). */
    void waitFor(BooleanSupplier done, String what) throws Exception {
        long deadline = System.nanoTime() + 600_000_000_000L;
        while (!done.getAsBoolean()) {
            for (Future<MjPlayer.Outcome> f : outcomes) {
                if (f.isDone()) fail("a player ended before " + what + ": " + f.get() + "; server log: " + read(server.log()));
            }
            if (System.nanoTime() > deadline) fail("no " + what + " within 10 minutes; server log: " + read(server.log()));
            Thread.sleep(50);
        }
    }

    static String read(Path log) {
        try {
            return Files.exists(log) ? Files.readString(log) : "(no log)";
        } catch (Exception e) {
            return "(unreadable: " + e + ")";
        }
    }

    @Override public void close() {
        server.stop();
        pool.shutdownNow();
        MJ_LOG.removeHandler(handler);
        MJ_LOG.setLevel(level);
    }
}

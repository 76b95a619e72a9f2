package phalanx.agent;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.ServerConnection;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.logging.Logger;

/**
 * The player's I/O (the connection has sent the scene: {@link #hello}): for every message the server sends, one reply from the
 * {@link PlayerRuntime} — every cycle without fail — and the think time of each cycle.
 */
public final class ThinkLoop {
    private static final Logger LOG = Logger.getLogger(ThinkLoop.class.getName());

    /** How the loop ended. */
    public record Outcome(long cycles, long malformed, String reason, PlayMode lastPlayMode) {
        public boolean gameOver() { return lastPlayMode == PlayMode.GAME_OVER; }
    }

    private final ServerConnection connection;
    private final PlayerOptions options;
    private final PlayerRuntime runtime;
    private final ThinkTimes times = new ThinkTimes();
    /** The JVM's per-thread CPU clock, null where it has none. */
    private final ThreadMXBean cpuClock = cpuClock();

    public ThinkLoop(ServerConnection connection, PlayerOptions options, PlayerRuntime runtime) {
        this.connection = connection;
        this.options = options;
        this.runtime = runtime;
    }

    /**
     * The first message, sent by the connection the moment it opens: the scene, with a syn for
     * agent-sync servers (docs/protocol.md).
     */
    public static String hello(PlayerOptions o) {
        return EffectorMessage.scene(o.robotType()) + "(syn)";
    }

    /** Runs until the connection ends; never throws for bad input. */
    public Outcome run() {
        FrameReader in = connection.reader();
        // stop.sh ends players with SIGTERM: say the think-time summary on the way out too.
        Thread summary = new Thread(() -> System.err.println("phalanx-player " + options.unum() + ": " + times.summary()));
        Runtime.getRuntime().addShutdownHook(summary);
        try {
            if (!awaitFirstMessage()) return end("the server accepted the connection but sent nothing for 30 s");
            while (true) {
                in.next();
                long start = System.nanoTime(), cpuStart = cpuNow();
                CharSequence reply = runtime.update(in.buffer(), in.length());
                if (runtime.cycles() > 1) { // thinking only, not the send
                    long wall = System.nanoTime() - start, cpu = cpuNow();
                    times.add(wall, cpu < 0 || cpuStart < 0 ? -1 : cpu - cpuStart);
                }
                connection.send(reply);
                if (runtime.cycles() % ThinkTimes.REPORT_EVERY == 0) LOG.info("beliefs " + runtime.beliefStats());
                if (runtime.cycles() == 2) LOG.info("in the game as " + options.team() + " " + options.unum());
            }
        } catch (ConnectionClosedException e) {
            return end("server closed the connection: " + e.getMessage());
        } catch (IOException e) {
            return end("connection lost: " + e.getMessage());
        }
    }

    /**
     * An agent-sync server can create the robot after the syn that came with the scene, and then waits
     * for a syn it never gets while the player waits for its first message (docs/protocol.md): repeat
     * the syn every 250 ms until the server speaks. Harmless without sync mode.
     */
    private boolean awaitFirstMessage() throws IOException {
        for (int i = 0; i < 120; i++) {
            if (connection.awaitData(250)) return true;
            connection.send("(syn)");
        }
        return false;
    }

    /** This thread's CPU time in ns, or -1 when not measured. */
    private long cpuNow() {
        return cpuClock == null ? -1 : cpuClock.getCurrentThreadCpuTime();
    }

    /**
     * The thread CPU clock if this JVM has one (HotSpot on Linux reads it with one clock_gettime),
     * switched on if it is off; null otherwise, and the think times then report wall time only.
     */
    private static ThreadMXBean cpuClock() {
        try {
            ThreadMXBean t = ManagementFactory.getThreadMXBean();
            if (!t.isCurrentThreadCpuTimeSupported()) return null;
            if (!t.isThreadCpuTimeEnabled()) t.setThreadCpuTimeEnabled(true);
            return t;
        } catch (UnsupportedOperationException | SecurityException e) {
            LOG.info("no thread CPU time on this JVM (" + e + "): think times are wall time only");
            return null;
        }
    }

    private Outcome end(String reason) {
        LOG.info(times.summary());
        LOG.info("beliefs " + runtime.beliefStats());
        return new Outcome(runtime.cycles(), runtime.malformed(), reason, runtime.playMode());
    }
}

package phalanx.bench.motion;

import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.wire.ServerConnection;

import java.io.Closeable;
import java.io.IOException;
import java.util.Locale;
import java.util.function.Function;

/**
 * What motion-bench and walk-bench share: the monitor port of a running server (its scene graph as
 * ground truth, read on a thread of its own, and the trainer commands) and one player of ours, player 1
 * of the team on the left, driven one message at a time. The benches add the trials.
 */
public final class BenchRig implements Closeable {
    /**
     * Every bench plays under this one name: the server keeps the left slot for a team name for a while
     * after its last player left, so a bench under another name right after could land on the right.
     */
    public static final String TEAM = "PhalanxBench";
    private final String tool;
    private final MonitorScene scene = new MonitorScene();
    private final ServerConnection monitor;
    private volatile String monitorError;
    private final PerceptionParser parser = new PerceptionParser();
    private ServerConnection agent;
    private Perception last;
    private long received;
    private int joinedUnum;
    private Side joinedSide;

    private BenchRig(String tool, ServerConnection monitor) {
        this.tool = tool;
        this.monitor = monitor;
    }

    /** Connects to the monitor port and starts reading the scene; {@code tool} prefixes messages. */
    public static BenchRig open(String host, int monitorPort, String tool) throws IOException {
        BenchRig rig = new BenchRig(tool, ServerConnection.connect(host, monitorPort, 10_000));
        Thread reader = new Thread(rig::readMonitor, "monitor");
        reader.setDaemon(true);
        reader.start();
        return rig;
    }

    private void readMonitor() {
        try {
            while (true) {
                monitor.reader().next();
                String text = monitor.reader().text();
                synchronized (scene) {
                    try {
                        scene.apply(text);
                    } catch (IllegalArgumentException e) {
                        monitorError = e.getMessage();
                    }
                    scene.notifyAll();
                }
            }
        } catch (IOException e) {
            monitorError = "monitor connection: " + e.getMessage();
            synchronized (scene) { scene.notifyAll(); }
        }
    }

    /**
     * Waits (at most {@code millis} of wall time) for the monitor's first full scene; the reason when none came.
     * A server whose monitor port is another's (it starts without one when the port is taken, silently), or
     * whose monitor control stopped (docs/protocol.md "Building and running the server": a float clock past 524,288 s with
     * {@code $monitorStep = 0.04}), sends none.
     */
    public String awaitScene(long millis) {
        long end = System.currentTimeMillis() + millis;
        synchronized (scene) {
            while (!scene.hasScene() && monitorError == null) {
                long left = end - System.currentTimeMillis();
                if (left <= 0) break;
                try {
                    scene.wait(left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            if (scene.hasScene()) return null;
            return monitorError != null ? monitorError
                    : String.format(Locale.ROOT, "the monitor port sent %s in %.0f s", scene.messages() == 0 ? "nothing" : scene.messages() + " messages but no scene", millis / 1000.0);
        }
    }

    /**
     * The ground truth of the cycle the player is in: the monitor's stream is read on its own thread and falls
     * behind the player's when reading is slower than the server (a server with real time off runs as fast as
     * the player answers; a cold or busy JVM, or another game on the machine, is enough). Before this wait a
     * bench so behind read its trials off pictures seconds old: kicks of "0.00 m, direction error NaN" or
     * 17 m at 147° (issue 22). Waits, at most {@code SYNC_MILLIS} of wall time, for a picture whose game time
     * is within {@link #PICTURE_SLACK} of the player's message (the player perceives a cycle before it is
     * stepped, the monitor sees it after; a picture from before a trainer {@code (time 0)} is far ahead).
     * Game time is the clock both share, exact since the benches reset it before each trial. After
     * {@code GIVE_UP} waits in a row that found no such picture the rig stops waiting (pictures from another
     * server never match): the trials' checks then say what is wrong.
     */
    private void awaitPicture(double gameTime) {
        if (unsynced) return;
        long end = System.currentTimeMillis() + SYNC_MILLIS;
        synchronized (scene) {
            double behind = gameTime - scene.time();
            if (tracking && behind > lag) lag = behind;
            while (!current(scene.time(), gameTime) && monitorError == null) {
                long left = end - System.currentTimeMillis();
                if (left <= 0) {
                    stale++;
                    if (++staleInARow >= GIVE_UP) {
                        unsynced = true;
                        System.err.printf(Locale.ROOT, "%s: the monitor's pictures have not matched our player's game time (%.2f s, pictures at %.2f s)"
                                + " for %d s: reading them as they come (are the agent and monitor ports one server's?)%n", tool, gameTime, scene.time(),
                                GIVE_UP * SYNC_MILLIS / 1000);
                    }
                    return;
                }
                try {
                    scene.wait(left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
            staleInARow = 0;
        }
    }

    /** A picture of game time {@code pictureTime} shows the cycle of a player message of game time {@code gameTime}. */
    static boolean current(double pictureTime, double gameTime) {
        return Math.abs(pictureTime - gameTime) <= PICTURE_SLACK;
    }

    /** Two cycles of game time (a picture every other cycle with the installed {@code $monitorStep = 0.04}) and rounding. */
    static final double PICTURE_SLACK = 0.045;
    private static final long SYNC_MILLIS = 2000;
    private static final int GIVE_UP = 3;
    private double lag;
    private boolean tracking, unsynced;
    private int stale, staleInARow;

    /** From now on the lag report counts (not while the server ran the clock alone before our player joined). */
    public void trackLag() {
        synchronized (scene) { tracking = true; }
    }

    /** Monitor pictures read so far. */
    public int pictures() { return scene(MonitorScene::messages); }

    /** The game time of the latest monitor picture (NaN before one had it). */
    public double pictureTime() { return scene(MonitorScene::time); }

    /** The most the monitor's picture was behind the player's message (game time, s), and how often it never caught up. */
    public String lagReport() {
        synchronized (scene) {
            return String.format(Locale.ROOT, "monitor: %d pictures, at most %.2f s of game time behind the player, %d cycles without a current picture%s",
                    scene.messages(), lag, stale, unsynced ? ", gave up waiting for them" : "");
        }
    }

    public void trainer(String command) throws IOException {
        synchronized (monitor) {
            monitor.send(command);
        }
    }

    /** A look at the scene graph, under its lock (the reader thread updates it). */
    public <T> T scene(Function<MonitorScene, T> look) {
        synchronized (scene) {
            return look.apply(scene);
        }
    }

    /** Player 1 of team Left: the benched robot. */
    public MonitorScene.Pose torso() { return scene(s -> s.torso(1, "Left")); }

    public double[] ball() { return scene(MonitorScene::ball); }

    /**
     * Connects player 1 of {@link #TEAM} as robot {@code type}: scene, the first message, then
     * {@code (init …)} which carries {@code (syn)}, so the caller's next step is {@link #receive()}.
     */
    public void connect(String host, int port, int type) throws IOException {
        agent = ServerConnection.connect(host, port, 10_000);
        agent.send(EffectorMessage.scene(type));
        receive();
        agent.send(EffectorMessage.init(1, TEAM));
    }

    /**
     * The next server message. Partial monitor updates stop matching the scene when the referee or a
     * trainer command changes it; a full scene every half second keeps the ground truth from going stale.
     */
    public Perception receive() throws IOException {
        agent.reader().next();
        if (++received % 25 == 0) trainer("(reqfullstate)");
        try {
            last = parser.parse(agent.reader().buffer(), 0, agent.reader().length());
        } catch (MalformedMessageException e) {
            System.err.println(tool + ": skipped a malformed server message: " + e.getMessage());
        }
        if (last != null && last.gameState() != null) {
            if (last.gameState().unum() != 0) {
                joinedUnum = last.gameState().unum();
                joinedSide = last.gameState().side();
            }
            if (!Double.isNaN(last.gameState().gameTime())) awaitPicture(last.gameState().gameTime());
        }
        if (monitorError != null) throw new IOException(monitorError);
        return last;
    }

    /**
     * Null when the server took our player as player 1 on the left (the robot the monitor's scene and the
     * trainer commands name), else what it made of it; call after the first message after {@code (init)}.
     */
    public String joinedAsPlayer1Left() {
        if (joinedUnum == 1 && joinedSide == Side.LEFT) return null;
        if (joinedUnum == 0) return "the server never said which player ours is (no unum in its messages)";
        return String.format(Locale.ROOT, "the server took our player as player %d on the %s, not player 1 on the left"
                + " (another team, or a %s player 1 left over from an earlier run: restart the server)", joinedUnum,
                joinedSide == null ? "unknown side" : joinedSide.name().toLowerCase(Locale.ROOT), TEAM);
    }

    /**
     * Null when the server is in agent-sync mode, else why not; call right after a reply. It reads the next
     * message (the caller answers it as usual): in sync mode the server steps once on our {@code (syn)}, sends
     * that one message and waits; without it, it goes on stepping (with real time off, thousands of cycles a
     * second) and our player reads pictures of the past while its replies act on the present. The benches
     * count cycles and so need sync mode.
     */
    public String syncModeProblem() throws IOException {
        try {
            Thread.sleep(200);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        receive();
        if (!agent.awaitData(0)) return null;
        return "the server sent our player more than one message per reply: it is not in agent-sync mode"
                + " (set $agentSyncMode = true in the spark.rb it reads, ~/.simspark/spark.rb, or in its --script-path script; docs/protocol.md)";
    }

    /** The last message received. */
    public Perception last() { return last; }

    /** Sends the player's reply (effectors and syn). */
    public void send(CharSequence message) throws IOException { agent.send(message); }

    public void disconnect() throws IOException {
        if (agent != null) agent.close();
        agent = null;
    }

    @Override
    public void close() throws IOException {
        disconnect();
        monitor.close();
    }
}

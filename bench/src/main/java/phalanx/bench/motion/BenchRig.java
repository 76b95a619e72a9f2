package phalanx.bench.motion;

import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.wire.ServerConnection;

import java.io.Closeable;
import java.io.IOException;
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
                }
            }
        } catch (IOException e) {
            monitorError = "monitor connection: " + e.getMessage();
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
        if (monitorError != null) throw new IOException(monitorError);
        return last;
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

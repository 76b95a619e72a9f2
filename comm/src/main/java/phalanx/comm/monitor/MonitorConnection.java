package phalanx.comm.monitor;

import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.ServerConnection;
import phalanx.comm.wire.WireException;

import java.io.IOException;

/**
 * A client of the server's monitor port (3200): reads the monitor stream and sends trainer
 * commands (docs/protocol.md, Trainer). Keeps the {@link MatchState} up to date as it reads.
 */
public final class MonitorConnection implements AutoCloseable {
    private final ServerConnection connection;
    private final MonitorHeader header = new MonitorHeader();
    private MatchState state = MatchState.INITIAL;

    private MonitorConnection(ServerConnection connection) { this.connection = connection; }

    public static MonitorConnection connect(String host, int port, long giveUpAfterMillis) throws WireException {
        return new MonitorConnection(ServerConnection.connect(host, port, giveUpAfterMillis));
    }

    /** Reads the next monitor message and returns it as text. */
    public String next() throws IOException {
        FrameReader r = connection.reader();
        r.next();
        String m = r.text();
        state = header.apply(state, m);
        return m;
    }

    public MatchState state() { return state; }

    /** Sends a trainer command such as {@code (playMode PlayOn)} or {@code (kickOff Left)}. */
    public void command(String trainerCommand) throws IOException { connection.send(trainerCommand); }

    public void kickOff(String side) throws IOException { command("(kickOff " + side + ")"); }
    public void playMode(String mode) throws IOException { command("(playMode " + mode + ")"); }
    public void moveBall(double x, double y, double z) throws IOException { command("(ball (pos " + x + " " + y + " " + z + "))"); }
    public void requestFullState() throws IOException { command("(reqfullstate)"); }

    @Override public void close() { connection.close(); }
}

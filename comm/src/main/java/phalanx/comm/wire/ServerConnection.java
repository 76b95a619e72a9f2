package phalanx.comm.wire;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;

/**
 * A player's TCP connection to rcssserver3d (or sim-stub): framing both ways over one socket.
 * {@link #connect} retries with back-off while nothing listens, up to a deadline.
 */
public final class ServerConnection implements AutoCloseable {
    private final Socket socket;
    private final BufferedInputStream in;
    private final FrameReader reader;
    private final FrameWriter writer;

    public ServerConnection(Socket socket) throws IOException {
        this.socket = socket;
        socket.setTcpNoDelay(true); // one small message per cycle: never wait for Nagle
        this.in = new BufferedInputStream(socket.getInputStream(), 64 * 1024);
        this.reader = new FrameReader(in);
        this.writer = new FrameWriter(new BufferedOutputStream(socket.getOutputStream(), 8 * 1024));
    }

    /**
     * Connects, retrying with back-off (100 ms doubling to 2 s) while the port refuses, until
     * {@code giveUpAfterMillis} have passed. Throws a {@link WireException} naming host and port.
     */
    public static ServerConnection connect(String host, int port, long giveUpAfterMillis) throws WireException {
        return connect(host, port, giveUpAfterMillis, null);
    }

    /**
     * As {@link #connect(String, int, long)}, sending {@code hello} the moment the connection opens.
     * A player's scene message must come at once: an agent-sync server that accepts a connection and
     * gets nothing for a few hundred milliseconds never creates the robot and stalls (docs/protocol.md).
     */
    public static ServerConnection connect(String host, int port, long giveUpAfterMillis, String hello) throws WireException {
        long deadline = System.nanoTime() + giveUpAfterMillis * 1_000_000L;
        long wait = 100;
        IOException last;
        while (true) {
            Socket s = new Socket();
            try {
                s.connect(new InetSocketAddress(host, port), 2000);
                ServerConnection c = new ServerConnection(s);
                if (hello != null) c.send(hello);
                return c;
            } catch (ConnectException | SocketTimeoutException e) {
                last = e;
            } catch (IOException e) {
                closeQuietly(s);
                throw new WireException("cannot connect to " + host + ":" + port + ": " + e.getMessage(), e);
            }
            closeQuietly(s);
            if (System.nanoTime() + wait * 1_000_000L > deadline) break;
            try {
                Thread.sleep(wait);
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
                break;
            }
            wait = Math.min(wait * 2, 2000);
        }
        throw new WireException("no server at " + host + ":" + port + " after " + giveUpAfterMillis / 1000.0
                + " s (" + last.getMessage() + ")", last);
    }

    public FrameReader reader() { return reader; }

    /**
     * Waits up to {@code millis} for the peer to send something, without reading it (so framing is
     * never cut by a timeout). True when bytes are waiting.
     */
    public boolean awaitData(long millis) throws IOException {
        long deadline = System.nanoTime() + millis * 1_000_000L;
        while (in.available() == 0) {
            if (System.nanoTime() >= deadline) return false;
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return true;
    }

    public void send(CharSequence message) throws IOException { writer.write(message); }

    @Override public void close() { closeQuietly(socket); }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing: nothing left to do
        }
    }
}

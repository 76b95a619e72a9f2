package phalanx.simstub;

import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.FrameWriter;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.BufferedWriter;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;

/**
 * A mock rcssserver3d that replays a recorded perceptor stream to one player over the real framing
 * (4-byte big-endian length) on 127.0.0.1.
 *
 * <p>It follows the order the recordings were made in (recordings README): the player sends
 * {@code (scene ...)}, gets perceptor line 1, sends {@code (init ...)} as its reply, gets line 2,
 * and so on; each reply releases the next line, like the real server in agent-sync mode. With
 * {@code paced} the lines go out every 20 ms whatever the player does. Every message received is
 * kept in order (and written to the log file, one per line, like {@code X_effectors.txt}).
 * After the last line and its reply the stub closes the connection.
 */
public final class ReplayServer implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(ReplayServer.class.getName());

    /** How the stub behaves. {@code replace} swaps perceptor line numbers (1-based) for other text. */
    public record Options(boolean paced, long replyTimeoutMillis, Path log, Map<Integer, String> replace) {
        public static Options defaults() { return new Options(false, 10_000, null, Map.of()); }
        public Options withLog(Path p) { return new Options(paced, replyTimeoutMillis, p, replace); }
        public Options withPaced(boolean p) { return new Options(p, replyTimeoutMillis, log, replace); }
        public Options withReplace(Map<Integer, String> r) { return new Options(paced, replyTimeoutMillis, log, r); }
    }

    /** What happened in one replay. */
    public record Result(int linesSent, List<String> received, int repliesWithoutSyn, String error) {
        public boolean handshakeOk() {
            return received.size() >= 2 && received.get(0).startsWith("(scene ") && received.get(1).startsWith("(init ");
        }
    }

    private final List<String> lines;
    private final Options options;
    private final ServerSocket listener;
    private final List<String> received = Collections.synchronizedList(new ArrayList<>());
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile Result result;
    private Thread thread;

    public ReplayServer(List<String> perceptorLines, int port, Options options) throws IOException {
        if (perceptorLines.isEmpty()) throw new IllegalArgumentException("nothing to replay: the recording has no lines");
        this.lines = List.copyOf(perceptorLines);
        this.options = options;
        this.listener = new ServerSocket(port, 1, InetAddress.getLoopbackAddress());
    }

    public int port() { return listener.getLocalPort(); }

    /** Starts serving one player in a background thread. */
    public ReplayServer start() {
        thread = new Thread(this::serve, "sim-stub");
        thread.setDaemon(true);
        thread.start();
        return this;
    }

    /** Waits for the replay to end (all lines sent and answered, or an error). */
    public Result await(long timeout, TimeUnit unit) throws InterruptedException {
        if (!done.await(timeout, unit)) return new Result(-1, List.copyOf(received), 0, "replay still running after " + timeout + " " + unit);
        return result;
    }

    private void serve() {
        int sent = 0, noSyn = 0;
        String error = null;
        try (BufferedWriter log = options.log() == null ? null : Files.newBufferedWriter(options.log(), StandardCharsets.ISO_8859_1);
             Socket s = listener.accept()) {
            s.setTcpNoDelay(true);
            s.setSoTimeout((int) options.replyTimeoutMillis());
            FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()));
            FrameWriter out = new FrameWriter(new BufferedOutputStream(s.getOutputStream()));
            String first = receive(in, log);
            if (!first.startsWith("(scene ")) throw new IOException("expected (scene ...) first, got: " + first);
            if (options.paced()) {
                Thread reader = new Thread(() -> drain(in, log), "sim-stub-reader");
                reader.setDaemon(true);
                reader.start();
                long next = System.nanoTime();
                for (int i = 0; i < lines.size(); i++) {
                    out.write(line(i));
                    sent++;
                    next += 20_000_000L;
                    long sleep = next - System.nanoTime();
                    if (sleep > 0) Thread.sleep(sleep / 1_000_000L, (int) (sleep % 1_000_000L));
                }
                reader.join(options.replyTimeoutMillis());
            } else {
                for (int i = 0; i < lines.size(); i++) {
                    out.write(line(i));
                    sent++;
                    String reply = receive(in, log);
                    if (i == 0 && !reply.startsWith("(init ")) throw new IOException("expected (init ...) as the reply to line 1, got: " + reply);
                    if (!reply.endsWith("(syn)")) noSyn++;
                }
            }
        } catch (ConnectionClosedException e) {
            error = "player closed the connection after " + sent + " lines: " + e.getMessage();
        } catch (SocketTimeoutException e) {
            error = "player did not answer line " + sent + " within " + options.replyTimeoutMillis() + " ms";
        } catch (IOException e) {
            error = e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            error = "interrupted";
        } finally {
            close();
        }
        if (error != null) LOG.warning("sim-stub: " + error);
        result = new Result(sent, List.copyOf(received), noSyn, error);
        done.countDown();
    }

    private String line(int i) {
        return options.replace().getOrDefault(i + 1, lines.get(i));
    }

    private String receive(FrameReader in, BufferedWriter log) throws IOException {
        in.next();
        String m = in.text();
        received.add(m);
        if (log != null) {
            log.write(m);
            log.newLine();
            log.flush();
        }
        return m;
    }

    private void drain(FrameReader in, BufferedWriter log) {
        try {
            while (true) receive(in, log);
        } catch (IOException e) {
            // the player left or the replay ended: nothing more to record
        }
    }

    @Override public void close() {
        try {
            listener.close();
        } catch (IOException e) {
            LOG.fine("closing the listener: " + e);
        }
    }
}

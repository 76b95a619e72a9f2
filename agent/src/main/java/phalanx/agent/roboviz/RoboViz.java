package phalanx.agent.roboviz;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.SocketException;
import java.net.UnknownHostException;
import java.util.logging.Logger;

/**
 * Debug drawing into RoboViz over its UDP draw protocol (port 32769). Shapes go into named sets
 * ({@code "animated.phalanx.L.7.beliefs"}); {@link #swap(String)} shows everything drawn into sets
 * starting with that prefix since its last swap. Commands are batched into datagrams of at most
 * {@value #MAX_DATAGRAM} bytes, split only between commands, and sent on {@link #flush()}.
 *
 * <p>Wire format (RoboViz's drawing protocol): a command is two type bytes, then numbers as six
 * ASCII characters each ({@code "%6f"} cut to six), colours as one unsigned byte per channel, and
 * strings ending in a zero byte. Coordinates are in the field frame (the left team's frame).
 *
 * <p>{@link #OFF} draws nothing and costs a branch; callers test {@link #on()} before building
 * anything expensive.
 */
public final class RoboViz {
    public static final int DEFAULT_PORT = 32769;
    static final int MAX_DATAGRAM = 1400;
    private static final Logger LOG = Logger.getLogger(RoboViz.class.getName());

    /** The drawer that draws nothing. */
    public static final RoboViz OFF = new RoboViz();

    private final DatagramSocket socket;
    private final InetAddress address;
    private final int port;
    private byte[] buf = new byte[8192];
    private int len;
    private boolean failed;

    private RoboViz() {
        socket = null;
        address = null;
        port = 0;
    }

    private RoboViz(DatagramSocket socket, InetAddress address, int port) {
        this.socket = socket;
        this.address = address;
        this.port = port;
    }

    /** A drawer sending to {@code host[:port]}; the port defaults to 32769. */
    public static RoboViz to(String hostAndPort) throws UnknownHostException, SocketException {
        String host = hostAndPort;
        int port = DEFAULT_PORT;
        int colon = hostAndPort.lastIndexOf(':');
        if (colon > 0) {
            host = hostAndPort.substring(0, colon);
            try {
                port = Integer.parseInt(hostAndPort.substring(colon + 1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("--roboviz port must be a number: '" + hostAndPort + "'");
            }
            if (port < 1 || port > 65535) throw new IllegalArgumentException("--roboviz port must be 1-65535: '" + hostAndPort + "'");
        }
        return new RoboViz(new DatagramSocket(), InetAddress.getByName(host), port);
    }

    public boolean on() { return socket != null; }

    /** Shows what was drawn into sets starting with {@code prefix} since the last swap. */
    public RoboViz swap(String prefix) {
        if (!on()) return this;
        type(0, 0);
        string(prefix);
        return end();
    }

    public RoboViz circle(double x, double y, double radius, double thickness, int rgb, String set) {
        if (!on()) return this;
        type(1, 0);
        num(x); num(y); num(radius); num(thickness);
        rgb(rgb);
        string(set);
        return end();
    }

    public RoboViz line(double x1, double y1, double z1, double x2, double y2, double z2, double thickness, int rgb, String set) {
        if (!on()) return this;
        type(1, 1);
        num(x1); num(y1); num(z1); num(x2); num(y2); num(z2); num(thickness);
        rgb(rgb);
        string(set);
        return end();
    }

    public RoboViz point(double x, double y, double z, double size, int rgb, String set) {
        if (!on()) return this;
        type(1, 2);
        num(x); num(y); num(z); num(size);
        rgb(rgb);
        string(set);
        return end();
    }

    public RoboViz sphere(double x, double y, double z, double radius, int rgb, String set) {
        if (!on()) return this;
        type(1, 3);
        num(x); num(y); num(z); num(radius);
        rgb(rgb);
        string(set);
        return end();
    }

    /** A text label at a point. */
    public RoboViz annotation(String text, double x, double y, double z, int rgb, String set) {
        if (!on()) return this;
        type(2, 0);
        num(x); num(y); num(z);
        rgb(rgb);
        string(text);
        string(set);
        return end();
    }

    /** Sends what is buffered. A send error is logged once and drawing stops: never a player's problem. */
    public void flush() {
        if (!on() || len == 0) return;
        try {
            // Pack whole commands into datagrams of at most MAX_DATAGRAM bytes.
            int start = 0, prev = 0;
            for (int k = 0; k < commands; k++) {
                int e = commandEnds[k];
                if (e - start > MAX_DATAGRAM && prev > start) {
                    send(start, prev);
                    start = prev;
                }
                prev = e;
            }
            send(start, len);
        } catch (IOException e) {
            if (!failed) LOG.warning("RoboViz drawing to " + address + ":" + port + " failed, going on without it: " + e.getMessage());
            failed = true;
        }
        len = 0;
        commands = 0;
    }

    // ---- encoding ------------------------------------------------------------------------------

    private int[] commandEnds = new int[256];
    private int commands;

    private void send(int from, int to) throws IOException {
        if (!failed) socket.send(new DatagramPacket(buf, from, to - from, address, port));
    }

    private RoboViz end() {
        if (commands == commandEnds.length) commandEnds = java.util.Arrays.copyOf(commandEnds, commands * 2);
        commandEnds[commands++] = len;
        return this;
    }

    private void type(int a, int b) {
        ensure(2);
        buf[len++] = (byte) a;
        buf[len++] = (byte) b;
    }

    private void rgb(int rgb) {
        ensure(3);
        buf[len++] = (byte) (rgb >> 16);
        buf[len++] = (byte) (rgb >> 8);
        buf[len++] = (byte) rgb;
    }

    private void string(String s) {
        ensure(s.length() + 1);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            buf[len++] = (byte) (c < 0x80 && c != 0 ? c : '?');
        }
        buf[len++] = 0;
    }

    /** Six ASCII characters, as C's "%6f" cut to six: "1.5000", "-12.34", "123.45". */
    private void num(double v) {
        ensure(6);
        if (!Double.isFinite(v)) v = 0;
        v = Math.max(-99999, Math.min(999999, v));
        String s = String.format(java.util.Locale.ROOT, "%f", v);
        for (int i = 0; i < 6; i++) buf[len++] = (byte) (i < s.length() ? s.charAt(i) : '0');
    }

    private void ensure(int n) {
        if (len + n > buf.length) buf = java.util.Arrays.copyOf(buf, Math.max(buf.length * 2, len + n));
    }
}

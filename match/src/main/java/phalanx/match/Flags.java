package phalanx.match;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/** Flag values the benches and the match tools read the same way; each error names the flag. */
public final class Flags {
    private Flags() { }

    /** Where every tool finds the server unless told otherwise (rcssserver3d's own defaults). */
    public static final String HOST = "127.0.0.1";
    public static final int AGENT_PORT = 3100, MONITOR_PORT = 3200;
    /** The server flags every tool that talks to rcssserver3d reads, with their defaults. */
    public static final class Server {
        public String host = HOST;
        public int port = AGENT_PORT;
        public int monitorPort = MONITOR_PORT;

        /** Takes {@code --host}, {@code --port} or {@code --monitor-port}; false for any other flag. */
        public boolean read(String flag, String v) {
            switch (flag) {
                case "--host" -> host = v;
                case "--port" -> port = port(flag, v);
                case "--monitor-port" -> monitorPort = port(flag, v);
                default -> { return false; }
            }
            return true;
        }
    }

    /** The server flags' part of a usage line. */
    public static final String SERVER_USAGE = "[--host " + HOST + "] [--port " + AGENT_PORT + "] [--monitor-port " + MONITOR_PORT + "]";

    /**
     * A command line as its flags in order, each {@code {flag, value}}: {@code --help} or {@code -h}
     * throws the usage, a flag named in {@code switches} stands alone (value "true"), any other needs
     * a value. What each flag means is the caller's; an unknown one goes to {@link #unknown}.
     */
    public static List<String[]> pairs(String[] args, String usage, Set<String> switches) {
        List<String[]> out = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String flag = args[i];
            if (flag.equals("--help") || flag.equals("-h")) throw new IllegalArgumentException(usage);
            if (switches.contains(flag)) {
                out.add(new String[] {flag, "true"});
                continue;
            }
            if (i + 1 >= args.length) throw new IllegalArgumentException(flag + " needs a value\n" + usage);
            out.add(new String[] {flag, args[++i]});
        }
        return out;
    }

    /** The error for a flag the tool does not know. */
    public static IllegalArgumentException unknown(String flag, String usage) {
        return new IllegalArgumentException("unknown flag '" + flag + "'\n" + usage);
    }

    /** A TCP port, 1-65535. */
    public static int port(String flag, String v) { return (int) number(flag, v, 1, 65535, true); }

    /** A number in [min, max]; {@code whole} wants an integer. */
    public static double number(String flag, String v, double min, double max, boolean whole) {
        double d;
        try {
            d = whole ? Integer.parseInt(v) : Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(flag + " needs " + (whole ? "a whole number" : "a number") + ", got '" + v + "'");
        }
        if (!(d >= min && d <= max)) throw new IllegalArgumentException(flag + " must be in [" + fmt(min) + ", " + fmt(max) + "], got " + v);
        return d;
    }

    /** A comma list of robot types 0-4, none twice. */
    public static List<Integer> types(String flag, String v) {
        List<Integer> t = new ArrayList<>();
        for (String s : v.split(",")) {
            int n = (int) number(flag, s.strip(), 0, 4, true);
            if (t.contains(n)) throw new IllegalArgumentException(flag + " lists " + n + " twice");
            t.add(n);
        }
        return List.copyOf(t);
    }

    private static String fmt(double d) { return d == Math.rint(d) ? String.valueOf((long) d) : String.valueOf(d); }
}

package phalanx.match;

import java.util.ArrayList;
import java.util.List;

/** Flag values the benches and the match tools read the same way; each error names the flag. */
public final class Flags {
    private Flags() { }

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

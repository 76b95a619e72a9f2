package phalanx.match;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** Command-line options {@code --name value} and flags {@code --name}; every mistake is a specific message. */
final class Args {
    private final Map<String, List<String>> values = new HashMap<>();
    private final Set<String> flags;

    Args(String[] argv, Set<String> valued, Set<String> flags, String program) {
        this.flags = flags;
        for (int i = 0; i < argv.length; i++) {
            String a = argv[i];
            if (!a.startsWith("--")) throw new IllegalArgumentException(program + ": unexpected argument '" + a + "'");
            String name = a.substring(2);
            if (flags.contains(name)) {
                values.computeIfAbsent(name, k -> new ArrayList<>()).add("true");
            } else if (valued.contains(name)) {
                if (i + 1 >= argv.length) throw new IllegalArgumentException(program + ": " + a + " needs a value");
                values.computeIfAbsent(name, k -> new ArrayList<>()).add(argv[++i]);
            } else {
                throw new IllegalArgumentException(program + ": unknown option " + a);
            }
        }
    }

    boolean flag(String name) { return values.containsKey(name); }
    List<String> all(String name) { return values.getOrDefault(name, List.of()); }
    String get(String name, String def) {
        List<String> v = values.get(name);
        return v == null ? def : v.get(v.size() - 1);
    }

    double number(String name, double def, double min, double max) {
        String v = get(name, null);
        if (v == null) return def;
        try {
            double d = Double.parseDouble(v);
            if (d < min || d > max || Double.isNaN(d)) throw new NumberFormatException();
            return d;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--" + name + " must be a number from " + fmt(min) + " to " + fmt(max) + ", got '" + v + "'");
        }
    }

    int integer(String name, int def, int min, int max) {
        double d = number(name, def, min, max);
        if (d != Math.rint(d)) throw new IllegalArgumentException("--" + name + " must be a whole number, got '" + get(name, "") + "'");
        return (int) d;
    }

    private static String fmt(double d) { return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d); }
}

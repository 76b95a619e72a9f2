package phalanx.bench.motion;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Per figure of one robot type (walk, turn_left, a kick or a dive motion, getup): how many trials measured
 * something and, for those that did not, each reason with its count, in the order first seen.
 */
final class Tally {
    private final Map<String, int[]> measured = new LinkedHashMap<>();
    private final Map<String, Map<String, Integer>> reasons = new LinkedHashMap<>();

    void measured(String figure) { measured.computeIfAbsent(figure, f -> new int[1])[0]++; }

    void unmeasured(String figure, String why) {
        measured.computeIfAbsent(figure, f -> new int[1]);
        reasons.computeIfAbsent(figure, f -> new LinkedHashMap<>()).merge(why, 1, Integer::sum);
    }

    int measuredCount(String figure) {
        int[] m = measured.get(figure);
        return m == null ? 0 : m[0];
    }

    int unmeasuredCount(String figure) {
        Map<String, Integer> r = reasons.get(figure);
        return r == null ? 0 : r.values().stream().mapToInt(Integer::intValue).sum();
    }

    /** Figures that had trials, in the order first seen. */
    List<String> figures() { return new ArrayList<>(measured.keySet()); }

    /** Figures with trials of which none measured anything: their summary value would be no result. */
    List<String> nothingMeasured() {
        List<String> l = new ArrayList<>();
        for (var e : measured.entrySet()) if (e.getValue()[0] == 0) l.add(e.getKey());
        return l;
    }

    /** One line per figure that had unmeasured trials: "figure: k of n trials measured nothing: reason (×c); ...". */
    List<String> lines() {
        List<String> l = new ArrayList<>();
        for (var e : reasons.entrySet()) {
            int bad = unmeasuredCount(e.getKey()), all = bad + measuredCount(e.getKey());
            StringBuilder sb = new StringBuilder(e.getKey()).append(": ").append(bad).append(" of ").append(all).append(" trials measured nothing: ");
            String sep = "";
            for (var r : e.getValue().entrySet()) {
                sb.append(sep).append(r.getKey());
                if (r.getValue() > 1) sb.append(" (x").append(r.getValue()).append(')');
                sep = "; ";
            }
            l.add(sb.toString());
        }
        return l;
    }
}

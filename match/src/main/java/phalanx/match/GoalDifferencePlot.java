package phalanx.match;

import java.util.List;
import java.util.Locale;

/**
 * An SVG plot of the goal difference per opponent: every counted game as a dot, the mean as a bar
 * and ± one standard deviation as a whisker. Pure: rows in, SVG text out.
 */
public final class GoalDifferencePlot {
    private GoalDifferencePlot() { }

    public static String svg(String us, List<Standings.OpponentRow> rows) {
        int slot = 110, left = 60, top = 40, height = 260;
        int width = left + 20 + Math.max(1, rows.size()) * slot;
        int max = 1;
        for (Standings.OpponentRow r : rows) {
            for (int d : r.differences()) max = Math.max(max, Math.abs(d));
            if (r.games() > 0) max = Math.max(max, (int) Math.ceil(Math.abs(r.averageDifference()) + r.spread()));
        }
        final int lim = max;
        java.util.function.DoubleUnaryOperator y = v -> top + height / 2.0 - v / lim * (height / 2.0);
        StringBuilder s = new StringBuilder();
        s.append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">%n",
                width, top + height + 50));
        s.append("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
        s.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"20\" font-size=\"14\">Goal difference of %s per opponent (dots: games; bar: mean; whisker: ±1 sd)</text>%n",
                left, esc(us)));
        for (int v = -lim; v <= lim; v++) {
            double yy = y.applyAsDouble(v);
            s.append(String.format(Locale.ROOT, "<line x1=\"%d\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>%n",
                    left, width - 10, yy, yy, v == 0 ? "black" : "#ddd"));
            s.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%+d</text>%n", left - 6, yy + 4, v));
        }
        for (int i = 0; i < rows.size(); i++) {
            Standings.OpponentRow r = rows.get(i);
            double cx = left + slot * (i + 0.5);
            if (r.games() > 0) {
                double m = r.averageDifference();
                double y0 = y.applyAsDouble(0), ym = y.applyAsDouble(m);
                s.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"40\" height=\"%.1f\" fill=\"%s\" opacity=\"0.5\"/>%n",
                        cx - 20, Math.min(y0, ym), Math.abs(ym - y0), m >= 0 ? "#2a7" : "#c44"));
                double hi = y.applyAsDouble(m + r.spread()), lo = y.applyAsDouble(m - r.spread());
                s.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"black\"/>%n", cx, cx, hi, lo));
                s.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"black\"/>%n", cx - 8, cx + 8, hi, hi));
                s.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"black\"/>%n", cx - 8, cx + 8, lo, lo));
                List<Integer> d = r.differences();
                for (int k = 0; k < d.size(); k++) {
                    double jitter = d.size() == 1 ? 0 : (k / (d.size() - 1.0) - 0.5) * 30;
                    s.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"black\"/>%n", cx + jitter, y.applyAsDouble(d.get(k))));
                }
            }
            s.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>%n", cx, top + height + 20, esc(r.opponent())));
            s.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\" fill=\"#555\">%d game%s%s</text>%n",
                    cx, top + height + 36, r.games(), r.games() == 1 ? "" : "s", r.notCounted() > 0 ? " +" + r.notCounted() + " n/c" : ""));
        }
        s.append("</svg>\n");
        return s.toString();
    }

    private static String esc(String t) {
        return t.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}

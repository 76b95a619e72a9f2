package phalanx.bench.coordination;

import java.util.Locale;
import phalanx.coordination.Action;
import phalanx.coordination.Assignment;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.coordination.beliefs.ReportType;
import phalanx.coordination.formation.Role;
import phalanx.coordination.subsets.Subset;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * A picture of one coordination round as SVG text (no library): the field in the team's own frame (our
 * goal on the left), the ball, every player coloured by subset, the active candidates, the formation's
 * role positions, and each assignment as an arrow from the player to its target with its role.
 */
public final class PlanSvg {
    private static final double MARGIN = 1.5;      // metres of grass around the lines
    private static final double SCALE = 30;        // pixels per metre
    private static final int LEGEND = 64;          // pixels below the field

    private PlanSvg() {}

    public static String render(TeamPlan plan, String title) {
        FieldSpec f = plan.beliefs().field();
        double hl = f.halfLength(), hw = f.halfWidth();
        double w = (f.length() + 2 * MARGIN) * SCALE, h = (f.width() + 2 * MARGIN) * SCALE;
        Svg s = new Svg(hl, hw);
        StringBuilder o = s.out;
        o.append(String.format(Locale.ROOT,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"DejaVu Sans, Arial, sans-serif\">%n",
                w, h + LEGEND, w, h + LEGEND));
        o.append("<defs>");
        for (String[] c : new String[][]{{"active", "#d32f2f"}, {"support", "#1565c0"}, {"gk", "#f9a825"}}) {
            o.append(String.format("<marker id=\"arrow-%s\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"%s\"/></marker>", c[0], c[1]));
        }
        o.append("</defs>\n");
        o.append(String.format(Locale.ROOT, "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" fill=\"#2e7d32\"/>%n", w, h));
        o.append(String.format(Locale.ROOT, "<rect x=\"0\" y=\"%.0f\" width=\"%.0f\" height=\"%d\" fill=\"#fafafa\"/>%n", h, w, LEGEND));

        // Lines.
        String line = "stroke=\"white\" stroke-width=\"2\" fill=\"none\"";
        s.rect(-hl, hw, hl, -hw, line);
        s.line(0, hw, 0, -hw, line);
        o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" %s/>%n", s.x(0), s.y(0), f.centreRadius() * SCALE, line));
        for (int side : new int[]{-1, 1}) {
            double gx = side * hl;
            s.rect(gx, f.penaltyWidth() / 2, gx - side * f.penaltyDepth(), -f.penaltyWidth() / 2, line);
            s.rect(gx, f.goalWidth() / 2, gx + side * 0.6, -f.goalWidth() / 2,
                    "stroke=\"white\" stroke-width=\"2\" fill=\"" + (side < 0 ? "#fff59d" : "#ef9a9a") + "\" fill-opacity=\"0.6\"");
        }
        s.text(-hl + 0.2, -hw - 0.9, "our goal ←", 13, "white", "start", false);
        s.text(hl - 0.2, -hw - 0.9, "→ their goal", 13, "white", "end", false);

        // Formation role positions (grey squares; dropped roles dashed).
        for (var e : plan.formation().positions().entrySet()) {
            Vector2 p = e.getValue();
            boolean dropped = plan.droppedRoles().contains(e.getKey());
            o.append(String.format(Locale.ROOT,
                    "<rect x=\"%.1f\" y=\"%.1f\" width=\"12\" height=\"12\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"%s/>%n",
                    s.x(p.x()) - 6, s.y(p.y()) - 6, dropped ? "#ffcdd2" : "#c8e6c9", dropped ? " stroke-dasharray=\"3,2\"" : ""));
            boolean taken = false;   // a support player's target sits on it and carries the label
            for (Assignment a : plan.assignments()) taken |= a.target() != null && a.target().distanceTo(p) < 0.05;
            if (!taken)
                s.text(p.x() + 0.25, p.y() - 0.55, e.getKey().name() + (dropped ? " (dropped)" : ""), 10, dropped ? "#ffcdd2" : "#c8e6c9", "start", false);
        }

        // Active candidates.
        for (Vector2 c : plan.activeCandidates())
            o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"#ffb74d\" stroke=\"#e65100\" stroke-width=\"1\"/>%n", s.x(c.x()), s.y(c.y())));

        // Assignments: arrows first, players on top.
        for (Assignment a : plan.assignments()) {
            PlayerBelief b = plan.beliefs().player(a.id());
            if (a.target() == null || b == null || b.position() == null) continue;
            String kind = a.subset() == Subset.ACTIVE ? "active" : a.subset() == Subset.GOALKEEPER ? "gk" : "support";
            String colour = colour(a.subset());
            Vector2 from = b.position(), to = a.target();
            if (from.distanceTo(to) > 0.3) {
                Vector2 start = from.plus(to.minus(from).times(0.35 / from.distanceTo(to)));
                o.append(String.format(Locale.ROOT,
                        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%s\" marker-end=\"url(#arrow-%s)\"%s/>%n",
                        s.x(start.x()), s.y(start.y()), s.x(to.x()), s.y(to.y()), colour, a.onBall() ? "3.5" : "2", kind,
                        a.subset() == Subset.SUPPORT ? " stroke-dasharray=\"7,4\"" : ""));
            }
            String label = a.onBall() ? a.role() + " on ball" : String.valueOf(a.role());
            s.text(to.x() + 0.3, to.y() + 0.25, label, 12, "white", "start", true);
        }
        Vector2 ball = plan.ball();
        o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5.5\" fill=\"#ff9800\" stroke=\"white\" stroke-width=\"2\"/>%n", s.x(ball.x()), s.y(ball.y())));
        for (PlayerBelief b : plan.beliefs().players()) {
            if (b.position() == null) continue;
            Assignment a = plan.assignment(b.id());
            Subset sub = a == null ? Subset.INACTIVE : a.subset();
            String dash = b.type() == ReportType.B ? " stroke-dasharray=\"3,2\"" : "";
            o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"10\" fill=\"%s\" stroke=\"white\" stroke-width=\"1.5\"%s/>%n",
                    s.x(b.position().x()), s.y(b.position().y()), colour(sub), dash));
            o.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" font-weight=\"bold\" fill=\"%s\" text-anchor=\"middle\">%d</text>%n",
                    s.x(b.position().x()), s.y(b.position().y()) + 4, sub == Subset.GOALKEEPER ? "black" : "white", b.id()));
            if (b.fallen()) s.text(b.position().x() + 0.4, b.position().y() - 0.6, "fallen", 10, "#eeeeee", "start", false);
        }

        // Title and legend.
        s.text(-hl - MARGIN + 0.3, hw + MARGIN - 0.6, title, 15, "white", "start", true);
        s.text(-hl - MARGIN + 0.3, hw + MARGIN - 1.15, String.format(Locale.ROOT,
                "mode %s · ball (%.1f, %.1f) · %s candidates · support mappings scored: %d%s", plan.mode(), ball.x(), ball.y(),
                plan.activeCandidates().isEmpty() ? "no" : plan.defensive() ? "defensive" : "offensive",
                plan.supportEvaluated(), plan.warnings().isEmpty() ? "" : " · " + plan.warnings().size() + " warning(s)"), 12, "white", "start", false);
        double ly = h + 24;
        double lx = 16;
        for (Object[] item : new Object[][]{{Subset.GOALKEEPER, "goalkeeper"}, {Subset.ACTIVE, "active"},
                {Subset.SUPPORT, "support"}, {Subset.INACTIVE, "inactive"}}) {
            o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"8\" fill=\"%s\"/>%n", lx, ly - 4, colour((Subset) item[0])));
            o.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" fill=\"#212121\">%s</text>%n", lx + 13, ly, item[1]));
            lx += 110;
        }
        o.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"#ffb74d\" stroke=\"#e65100\"/><text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" fill=\"#212121\">active candidate (5.7)</text>%n", lx, ly - 4, lx + 10, ly));
        lx += 175;
        o.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"12\" height=\"12\" fill=\"#9e9e9e\" stroke=\"#616161\"/><text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" fill=\"#212121\">formation role (5.9)</text>%n", lx - 6, ly - 10, lx + 12, ly));
        o.append(String.format(Locale.ROOT, "<text x=\"16\" y=\"%.1f\" font-size=\"11\" fill=\"#424242\">solid arrow: active assignment (thick: on-ball) · dashed arrow: support assignment (5.12) · dashed ring: position inferred from a type B report</text>%n", ly + 24));
        o.append("</svg>\n");
        return o.toString();
    }

    private static String colour(Subset s) {
        return switch (s) {
            case GOALKEEPER -> "#f9a825";
            case ACTIVE -> "#d32f2f";
            case SUPPORT -> "#1565c0";
            case INACTIVE -> "#757575";
        };
    }

    /** Field metres to SVG pixels (y up on the field, down in SVG). */
    private static final class Svg {
        final StringBuilder out = new StringBuilder(16_384);
        final double hl, hw;

        Svg(double hl, double hw) { this.hl = hl; this.hw = hw; }

        double x(double fx) { return (fx + hl + MARGIN) * SCALE; }
        double y(double fy) { return (hw + MARGIN - fy) * SCALE; }

        void line(double x1, double y1, double x2, double y2, String attrs) {
            out.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>%n", x(x1), y(y1), x(x2), y(y2), attrs));
        }

        void rect(double x1, double y1, double x2, double y2, String attrs) {
            out.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" %s/>%n",
                    Math.min(x(x1), x(x2)), Math.min(y(y1), y(y2)), Math.abs(x(x2) - x(x1)), Math.abs(y(y2) - y(y1)), attrs));
        }

        void text(double fx, double fy, String text, int size, String fill, String anchor, boolean bold) {
            out.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\" fill=\"%s\" text-anchor=\"%s\"%s>%s</text>%n",
                    x(fx), y(fy), size, fill, anchor, bold ? " font-weight=\"bold\" stroke=\"#1b5e20\" stroke-width=\"0.4\"" : "", escape(text)));
        }
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}

package phalanx.coordination.active;

import java.util.ArrayList;
import java.util.List;
import phalanx.coordination.CoordinationConfig.ActivePositionsConfig;
import phalanx.coordination.features.FieldUtility;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * Phase 3 of Algorithm 3, "Determine Active Positions" (thesis 5.7). Ball in our half (x < 0): the
 * defensive rings, 12 positions at 1 m and 12 at 1.5 m, 30° apart, of which the ones with the LEAST
 * field utility survive, so they lie between the ball and our goal. Ball in their half: the offensive
 * rings, 12 at 2 m 30° apart and 24 at max{3, (|x|+|y|)/(L/2+W/2)} m 15° apart, of which the ones with
 * the HIGHEST utility survive, towards their goal. Positions outside or near the lines are dropped first;
 * at most {@code keep} (9) remain, best first.
 * <p>
 * On the field (|x|+|y|)/(L/2+W/2) never exceeds 1, so the outer offensive radius as printed is always
 * 3 m; it is implemented as printed.
 */
public final class ActivePositions {
    private ActivePositions() {}

    /** True when the ball is in our half and the candidates are defensive. */
    public static boolean defensive(Vector2 ball) { return ball.x() < 0; }

    public static List<Vector2> candidates(Vector2 ball, FieldSpec field, ActivePositionsConfig c) {
        boolean defensive = defensive(ball);
        List<Vector2> ring = new ArrayList<>(36);
        if (defensive) {
            addRing(ring, ball, c.defensiveInner(), c.defensiveCount(), field, c.fieldMargin());
            addRing(ring, ball, c.defensiveOuter(), c.defensiveCount(), field, c.fieldMargin());
        } else {
            double outer = Math.max(c.offensiveOuterMin(),
                    (Math.abs(ball.x()) + Math.abs(ball.y())) / (field.halfLength() + field.halfWidth()));
            addRing(ring, ball, c.offensiveInner(), c.offensiveInnerCount(), field, c.fieldMargin());
            addRing(ring, ball, outer, c.offensiveOuterCount(), field, c.fieldMargin());
        }
        int n = ring.size();
        double[] u = new double[n];
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            // Negated for defence so that "best first" is ascending in both cases.
            u[i] = defensive ? FieldUtility.of(ring.get(i), field) : -FieldUtility.of(ring.get(i), field);
            order[i] = i;
        }
        java.util.Arrays.sort(order, (a, b) -> Double.compare(u[a], u[b]));   // stable: ties keep ring order
        int keep = Math.min(c.keep(), n);
        List<Vector2> out = new ArrayList<>(keep);
        for (int i = 0; i < keep; i++) out.add(ring.get(order[i]));
        return out;
    }

    private static void addRing(List<Vector2> out, Vector2 centre, double radius, int count, FieldSpec field,
                                double margin) {
        for (int k = 0; k < count; k++) {
            Vector2 p = centre.plus(Vector2.polar(radius, k * 360.0 / count));
            if (field.contains(p, -margin)) out.add(p);
        }
    }
}

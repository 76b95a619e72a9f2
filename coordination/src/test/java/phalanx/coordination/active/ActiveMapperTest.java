package phalanx.coordination.active;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.ActiveWeights;
import phalanx.coordination.CoordinationConfig.CollisionConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

class ActiveMapperTest {
    private static final FieldSpec F = FieldSpec.V066;
    private static final ActiveWeights W = ActiveWeights.THESIS;
    private static final CollisionConfig C = CollisionConfig.THESIS;

    /** The thesis's cost written out term by term, independently of ActiveMapper.cost. */
    private static double reference(Vector2[] s, Vector2[] t) {
        double total = 0;
        for (int i = 0; i < 3; i++) {
            total += s[i].distanceTo(t[i]);
            total -= Math.abs(t[i].x() * (10 - Math.abs(t[i].y()))) / 7;
            for (int j = 0; j < 3; j++) {
                if (j == i) continue;
                total -= t[i].distanceTo(t[j]);
                total -= Math.abs(t[i].x() - t[j].x());
                total += collision(s[i], t[i], s[j], t[j]);
            }
        }
        return total;
    }

    /** Figure 5.8 by a different route: solve a + r·t = c + s·u with Cramer's rule. */
    private static double collision(Vector2 a, Vector2 b, Vector2 c, Vector2 d) {
        double a11 = b.x() - a.x(), a12 = -(d.x() - c.x()), a21 = b.y() - a.y(), a22 = -(d.y() - c.y());
        double det = a11 * a22 - a12 * a21;
        if (det == 0) return 0;
        double r1 = c.x() - a.x(), r2 = c.y() - a.y();
        double t = (r1 * a22 - a12 * r2) / det, u = (a11 * r2 - r1 * a21) / det;
        if (t < 0 || t > 1 || u < 0 || u > 1) return 0;
        Vector2 x = a.plus(b.minus(a).times(t));
        return Math.abs(x.distanceTo(a) - x.distanceTo(c)) <= 1.5 ? 100 : 2;
    }

    @Test
    void exhaustiveMappingMatchesBruteForceAndScores72Pairs() {
        Random rnd = new Random(5);
        for (int trial = 0; trial < 200; trial++) {
            Vector2 ball = new Vector2(rnd.nextDouble() * 26 - 13, rnd.nextDouble() * 16 - 8);
            List<Vector2> cand = ActivePositions.candidates(ball, F, phalanx.coordination.CoordinationConfig.ActivePositionsConfig.THESIS);
            if (cand.size() < 9) continue;
            Vector2 on = ball.plus(new Vector2(rnd.nextDouble() * 4 - 2, rnd.nextDouble() * 4 - 2));
            List<Vector2> others = List.of(ball.plus(new Vector2(rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4)),
                    ball.plus(new Vector2(rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4)));
            ActiveMapper.ActiveMapping m = ActiveMapper.map(on, ball, others, cand, F, W, C);
            assertEquals(72, m.evaluated());
            double best = Double.POSITIVE_INFINITY;
            for (int i = 0; i < 9; i++) for (int j = 0; j < 9; j++) {
                if (i == j) continue;
                best = Math.min(best, reference(new Vector2[]{on, others.get(0), others.get(1)},
                        new Vector2[]{ball, cand.get(i), cand.get(j)}));
            }
            assertEquals(best, m.cost(), 1e-9, "trial " + trial);
            assertEquals(best, reference(new Vector2[]{on, others.get(0), others.get(1)},
                    new Vector2[]{ball, cand.get(m.assignment()[0]), cand.get(m.assignment()[1])}), 1e-9);
        }
    }

    @Test
    void twoPlayersDoNotSwapSides() {
        // Ball at the origin, on-ball player behind it; players at (0, 3) and (0, -3); two candidates
        // (-1, 2) and (-1, -2). Crossing over would cost more distance and a likely collision.
        Vector2 ball = Vector2.ZERO;
        List<Vector2> cand = new ArrayList<>(List.of(new Vector2(-1, 2), new Vector2(-1, -2)));
        ActiveMapper.ActiveMapping m = ActiveMapper.map(new Vector2(-1, 0), ball,
                List.of(new Vector2(0, 3), new Vector2(0, -3)), cand, F, W, C);
        assertArrayEquals(new int[]{0, 1}, m.assignment());
        assertEquals(2, m.evaluated());
    }

    @Test
    void oneOrNoOtherPlayer() {
        List<Vector2> cand = List.of(new Vector2(-1, 1), new Vector2(-5, 1));
        ActiveMapper.ActiveMapping one = ActiveMapper.map(new Vector2(-1, 0), Vector2.ZERO, List.of(new Vector2(-1, 2)), cand, F, W, C);
        assertEquals(2, one.evaluated());
        ActiveMapper.ActiveMapping none = ActiveMapper.map(new Vector2(-1, 0), Vector2.ZERO, List.of(), cand, F, W, C);
        assertEquals(0, none.assignment().length);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ActiveMapper.map(Vector2.ZERO, Vector2.ZERO,
                List.of(Vector2.ZERO, Vector2.ZERO), List.of(Vector2.ZERO), F, W, C));
        assertEquals("2 players but only 1 candidate positions", e.getMessage());
    }
}

package phalanx.coordination.active;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.ActivePositionsConfig;
import phalanx.coordination.features.FieldUtility;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

class ActivePositionsTest {
    private static final FieldSpec F = FieldSpec.V066;
    private static final ActivePositionsConfig C = ActivePositionsConfig.THESIS;

    @Test
    void defensiveCandidatesLieBetweenTheBallAndOurGoal() {
        // Figure 5.7 left: ball in our half on the centre line. By hand, the nine least utilities of the
        // 24 ring points are the ones at 180°, ±150° and ±120° (and one of the ±120° at 1.5 m): all behind.
        Vector2 ball = new Vector2(-5, 0);
        List<Vector2> c = ActivePositions.candidates(ball, F, C);
        assertTrue(ActivePositions.defensive(ball));
        assertEquals(9, c.size());
        for (Vector2 p : c) {
            assertTrue(p.x() <= ball.x() - 0.5 + 1e-9, "not behind the ball: " + p);
            double r = p.distanceTo(ball);
            assertTrue(Math.abs(r - 1) < 1e-9 || Math.abs(r - 1.5) < 1e-9, "not on a ring: " + p);
        }
        assertEquals(-6.5, c.get(0).x(), 1e-9);   // the least utility: straight back at 1.5 m
        assertEquals(0, c.get(0).y(), 1e-9);
    }

    @Test
    void offensiveCandidatesLieTowardsTheirGoal() {
        Vector2 ball = new Vector2(5, 0);
        List<Vector2> c = ActivePositions.candidates(ball, F, C);
        assertFalse(ActivePositions.defensive(ball));
        assertEquals(9, c.size());
        for (Vector2 p : c) {
            assertTrue(p.x() > ball.x() + 1.5, "not ahead of the ball: " + p);
            double r = p.distanceTo(ball);
            assertTrue(Math.abs(r - 2) < 1e-9 || Math.abs(r - 3) < 1e-9, "not on a ring: " + p);
        }
        assertEquals(new Vector2(8, 0).x(), c.get(0).x(), 1e-9);   // best: straight ahead at 3 m
    }

    @Test
    void candidatesAreSortedByUtilityAndKeepTheBestNine() {
        Vector2 ball = new Vector2(4, -3);
        List<Vector2> c = ActivePositions.candidates(ball, F, C);
        for (int i = 1; i < c.size(); i++)
            assertTrue(FieldUtility.of(c.get(i - 1), F) >= FieldUtility.of(c.get(i), F));
        // Every other ring point scores no better than the ninth.
        double ninth = FieldUtility.of(c.get(8), F);
        for (int k = 0; k < 24; k++) {
            Vector2 p = ball.plus(Vector2.polar(3, 15 * k));
            if (!c.contains(p)) assertTrue(FieldUtility.of(p, F) <= ninth + 1e-9);
        }
    }

    @Test
    void positionsNearOrOutsideTheLinesAreDropped() {
        for (Vector2 ball : List.of(new Vector2(14.8, 9.8), new Vector2(-14.8, -9.8), new Vector2(0, 10), new Vector2(-15, 0))) {
            List<Vector2> c = ActivePositions.candidates(ball, F, C);
            assertFalse(c.isEmpty(), "no candidate for ball " + ball);
            for (Vector2 p : c) assertTrue(F.contains(p, -C.fieldMargin()), p + " too near the lines for ball " + ball);
        }
        // In their corner only a quarter of the rings is left.
        assertTrue(ActivePositions.candidates(new Vector2(14.8, 9.8), F, C).size() < 9);
    }
}

package phalanx.coordination.formation;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

class FormationGeneratorTest {
    private static final FormationConfig C = FormationConfig.DEFAULT;

    /** The ball in each corner, at the middle of each line, on each spot, and beyond the lines. */
    private static List<Vector2> balls(FieldSpec f) {
        double hx = f.halfLength(), hy = f.halfWidth();
        List<Vector2> b = new ArrayList<>();
        for (double x : new double[]{-hx, -hx / 2, 0, hx / 2, hx})
            for (double y : new double[]{-hy, -hy / 2, 0, hy / 2, hy}) b.add(new Vector2(x, y));
        b.add(new Vector2(hx + 3, hy + 3));
        b.add(new Vector2(-hx - 3, 0));
        b.add(new Vector2(Double.NaN, 0));
        return b;
    }

    @ParameterizedTest
    @ValueSource(ints = {9, 11})
    void everyPositionStaysInsideTheFieldAndApartForEveryBall(int players) {
        FieldSpec f = FieldSpec.forPlayers(players);
        for (Vector2 ball : balls(f)) {
            Formation form = FormationGenerator.generate(ball, f, C);
            assertEquals(Role.forPlayers(players).size(), form.positions().size());
            assertEquals(Role.forPlayers(players), new ArrayList<>(form.positions().keySet()));
            for (Map.Entry<Role, Vector2> e : form.positions().entrySet())
                assertTrue(f.contains(e.getValue(), -C.inset() + 1e-9), e.getKey() + " at " + e.getValue() + " for ball " + ball);
            List<Vector2> ps = new ArrayList<>(form.positions().values());
            for (int i = 0; i < ps.size(); i++)
                for (int j = i + 1; j < ps.size(); j++)
                    assertTrue(ps.get(i).distanceTo(ps.get(j)) > 0.3,
                            "two roles on one spot " + ps.get(i) + " for ball " + ball + ": " + form.positions());
        }
    }

    @Test
    void defenderCenterStandsTwoToThreeMetresOutOnTheGoalBallLine() {
        FieldSpec f = FieldSpec.V066;
        Vector2 goal = f.ownGoal();
        // Ball on our goal: 2 m. Ball in the far corner (the longest line): 3 m.
        assertEquals(2.0, FormationGenerator.generate(new Vector2(-15, 0), f, C).position(Role.DC).distanceTo(goal), 1e-9);
        Vector2 far = new Vector2(15, 10);
        Vector2 dc = FormationGenerator.generate(far, f, C).position(Role.DC);
        assertEquals(3.0, dc.distanceTo(goal), 1e-9);
        assertEquals(0, far.minus(goal).cross(dc.minus(goal)), 1e-9, "DC is on the goal-ball line");
        // Halfway: 2.5 m.
        Vector2 mid = goal.plus(far.minus(goal).times(0.5));
        assertEquals(2.5, FormationGenerator.generate(mid, f, C).position(Role.DC).distanceTo(goal), 1e-9);
    }

    @Test
    void defendersLeftAndRightAreOnTheirSides() {
        Formation form = FormationGenerator.generate(new Vector2(0, 0), FieldSpec.V066, C);
        assertEquals(C.defenderSpread(), form.position(Role.DL).y(), 1e-9);
        assertEquals(-C.defenderSpread(), form.position(Role.DR).y(), 1e-9);
        assertTrue(form.position(Role.FL).y() > form.position(Role.FC).y());
        assertTrue(form.position(Role.FR).y() < form.position(Role.FC).y());
        assertTrue(form.position(Role.ML).y() > form.position(Role.MC).y());
        assertTrue(form.position(Role.MR).y() < form.position(Role.MC).y());
    }

    @Test
    void forwardSupportAndMidfielderCenterFollowForwardCenterAtFixedDistances() {
        Formation form = FormationGenerator.generate(new Vector2(6, 2), FieldSpec.V066, C);
        Vector2 fc = form.position(Role.FC);
        assertEquals(new Vector2(6 - C.forwardBehind(), 2), fc);
        assertEquals(fc.x() - C.supportBehind(), form.position(Role.FS).x(), 1e-9);
        assertEquals(fc.x() - 2 * C.supportBehind(), form.position(Role.MC).x(), 1e-9);
        assertEquals(2, form.position(Role.MC).y(), 1e-9);
    }

    @Test
    void forwardsNeverDropBelowTheMiddle() {
        Formation form = FormationGenerator.generate(new Vector2(-12, 3), FieldSpec.V066, C);
        assertEquals(C.forwardMinX(), form.position(Role.FC).x(), 1e-9);
    }

    @Test
    void nineMidfieldersSupportForwardsInTheirHalfAndDefenceInOurs() {
        FieldSpec f = FieldSpec.V065;
        Formation attack = FormationGenerator.generate(new Vector2(6, 0), f, C);
        assertEquals(attack.position(Role.FC).x() - C.midfieldBehindForwards(), attack.position(Role.ML).x(), 1e-9);
        Formation defence = FormationGenerator.generate(new Vector2(-4, 0), f, C);
        assertEquals(defence.position(Role.DC).x() + C.midfieldAhead(), defence.position(Role.ML).x(), 1e-9);
    }
}

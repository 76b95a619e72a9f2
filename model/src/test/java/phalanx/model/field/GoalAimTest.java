package phalanx.model.field;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** FieldSpec.opponentGoalAim: the bisector of the posts' angle, checked with a ruler on the 30 x 20 field (goal at x = 15, posts at y = ±1.05). */
class GoalAimTest {
    private static final FieldSpec F = FieldSpec.V066;

    @Test
    void straightInFrontOrFarOutItIsTheCentre() {
        assertEquals(0, F.opponentGoalAim(new Vector2(10, 0), 0.15).y(), 1e-12);
        Vector2 far = F.opponentGoalAim(new Vector2(-5, 6), 0.15);
        assertEquals(15, far.x(), 1e-12);
        // from 20 m out, 6 m to the side, the two posts' directions differ by under 2 degrees: the aim is within 0.1 m of the centre
        assertEquals(0, far.y(), 0.1);
    }

    @Test
    void fromBesideThePostOnTheGoalLineItAimsIntoTheMouthAwayFromTheFarPost() {
        Vector2 ball = new Vector2(14.85, -1.11);   // a ball that lay 21 s there in a game (docs/matches.md, session 23)
        Vector2 aim = F.opponentGoalAim(ball, 0.15);
        // posts brought in to ±0.9: the distances to them are 2.016 and 0.258 m, so the bisector meets the line
        // 1.8 x 0.258 / 2.274 = 0.204 m from the near post
        assertEquals(-0.696, aim.y(), 1e-3);
        double aimDeg = aim.minus(ball).angleDeg(), nearDeg = new Vector2(15, -0.9).minus(ball).angleDeg(),
                farDeg = new Vector2(15, 0.9).minus(ball).angleDeg();
        assertEquals(aimDeg - nearDeg, farDeg - aimDeg, 1e-9, "the same window either side");
        // the centre would have been 82 degrees off the x axis, 3.7 degrees from the far post's 85.7
        assertTrue(aimDeg < 72, "aim " + aimDeg);
    }

    @Test
    void onOrBehindTheGoalLineOrWithoutAMouthItIsTheCentre() {
        assertEquals(new Vector2(15, 0), F.opponentGoalAim(new Vector2(15.2, 0.5), 0.15));
        assertEquals(new Vector2(15, 0), F.opponentGoalAim(null, 0.15));
        assertEquals(new Vector2(15, 0), F.opponentGoalAim(new Vector2(10, 3), 1.2));
    }
}

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

/** The referee's set-piece places (soccer_referee.py _penalize_misplaced_players) by hand, own frame, ssim field. */
class MjSetPieceTest {
    private static final MjField F = MjField.SSIM;
    private static final MjSetPiece.Config C = MjSetPiece.Config.DEFAULT;   // margin 1.0: targets 6.5 m out

    private static MjSetPiece left(String mode, Vector2 ball) { return MjSetPiece.of(mode, 1, F, ball, false, C); }

    @Test
    void theirFreeKickKickInAndCornerKeepEveryoneOutOfTheCircleRoundTheBall() {
        Vector2 ball = new Vector2(-5, 3);
        for (String mode : new String[] {"free_kick_right", "direct_free_kick_right", "KickIn_Right", "corner_kick_right"}) {
            MjSetPiece r = left(mode, ball);
            assertTrue(r.restricts(), mode);
            assertTrue(r.forbidden(new Vector2(-5 + 5.4, 3)), mode + ": 5.4 m from the ball");
            assertFalse(r.forbidden(new Vector2(-5 + 5.6, 3)), mode + ": 5.6 m");
            // a spot 2 m below the ball goes straight down to 6.5 m from it
            Vector2 a = r.allowed(new Vector2(-5, 1));
            assertEquals(-5, a.x(), 1e-9);
            assertEquals(3 - 6.5, a.y(), 1e-9);
            Vector2 far = new Vector2(10, 10);
            assertSame(far, r.allowed(far), mode + ": a place outside stays");
            // the one who would go to the ball: on its line to our goal (-27.5, 0), 6.5 m from it
            Vector2 wall = r.wall(ball, F);
            assertEquals(6.5, wall.distanceTo(ball), 1e-9);
            Vector2 toGoal = new Vector2(-27.5, 0).minus(ball);
            assertEquals(0, toGoal.cross(wall.minus(ball)), 1e-9, "on the line");
            assertTrue(wall.x() < ball.x());
        }
        assertFalse(left("free_kick_left", ball).restricts(), "our own free kick: nothing");
        assertFalse(left("KickIn_Left", ball).restricts());
        assertFalse(left("offside_right", ball).restricts(), "the referee places nobody in offside");
        assertFalse(left("PlayOn", ball).restricts());
        assertTrue(MjSetPiece.of("free_kick_left", -1, F, ball, false, C).restricts(), "for the right team free_kick_left is theirs");
        assertFalse(left("free_kick_right", null).restricts(), "no ball believed: nothing to keep from");
    }

    @Test
    void theirKickOffKeepsUsInOurHalfAndOutOfTheCentreCircle() {
        MjSetPiece r = left("KickOff_Right", Vector2.ZERO);
        assertTrue(r.forbidden(new Vector2(-1.1, 0)), "the formation's forward spot, 1.1 m behind the ball");
        assertTrue(r.forbidden(new Vector2(0.5, 10)), "their half");
        assertFalse(r.forbidden(new Vector2(-0.5, 10)));
        assertEquals(new Vector2(-6.5, 0), r.allowed(new Vector2(-1.1, 0)));
        Vector2 a = r.allowed(new Vector2(2, 3));
        assertTrue(a.x() <= -1 + 1e-9 && a.norm() >= 6.5 - 1e-9, "in our half, out of the circle: " + a);
        assertEquals(new Vector2(-1, 10), r.allowed(new Vector2(4, 10)), "out of their half only");
        assertEquals(new Vector2(-6.5, 0), r.wall(Vector2.ZERO, F));
    }

    @Test
    void theirGoalKickKeepsUsOutOfTheirGoalieAreaAndOurKickOffOutOfTheirHalfButTheTaker() {
        MjSetPiece g = left("goal_kick_right", new Vector2(25.5, 0));
        assertTrue(g.forbidden(new Vector2(24, 1)), "their goalie area: x >= 23.5, |y| <= 3.65");
        assertFalse(g.forbidden(new Vector2(23, 1)));
        assertFalse(g.forbidden(new Vector2(24, 4)));
        assertEquals(new Vector2(22.5, 1), g.allowed(new Vector2(24, 1)));
        MjSetPiece ours = left("KickOff_Left", Vector2.ZERO);
        assertTrue(ours.forbidden(new Vector2(0.5, 3)), "our kick-off: not in their half");
        assertEquals(new Vector2(-1, 3), ours.allowed(new Vector2(2, 3)));
        assertFalse(MjSetPiece.of("KickOff_Left", 1, F, Vector2.ZERO, true, C).restricts(), "the taker may go to the ball");
        assertFalse(left("goal_kick_left", new Vector2(-25.5, 0)).restricts(), "our goal kick: nothing");
    }

    /**
     * A point walker from one side of the circle to the other, 5 cm a step toward {@link MjSetPiece#via}: it never enters
     * the circle grown by half the margin, and gets to its target.
     */
    @Test
    void aWalkAcrossTheCircleGoesRoundIt() {
        Vector2 ball = new Vector2(-5, 3);
        MjSetPiece r = left("free_kick_right", ball);
        for (Vector2 from : new Vector2[] {new Vector2(-5, -8), new Vector2(5, 3), new Vector2(-12, 3.2), new Vector2(-5.1, -3.6)}) {
            Vector2 target = r.allowed(ball.plus(ball.minus(from)));   // straight through the ball, beyond it
            Vector2 self = from;
            double closest = Double.POSITIVE_INFINITY;
            int steps = 0;
            while (self.distanceTo(target) > 0.1 && steps++ < 2000) {
                Vector2 to = r.via(self, target, C).minus(self);
                self = self.plus(to.times(Math.min(0.05, to.norm()) / Math.max(1e-9, to.norm())));
                closest = Math.min(closest, self.distanceTo(ball));
            }
            assertTrue(steps < 2000, "from " + from + " it gets to " + target + ", at " + self);
            assertTrue(closest >= 6.0 - 1e-6, "from " + from + ": " + closest + " m from the ball at the closest");
        }
        Vector2 self = new Vector2(-5, -8), clear = new Vector2(-20, -8);
        assertSame(clear, r.via(self, clear, C), "a line that keeps out: straight there");
    }

    @Test
    void aPlaceBeyondTheLinesSlidesAlongThemOutOfTheCircle() {
        Vector2 ball = new Vector2(-24, 3);
        MjSetPiece r = left("free_kick_right", ball);
        Vector2 keeper = new Vector2(-26.5, 1.2);
        Vector2 plain = r.allowed(keeper);
        assertTrue(plain.x() < -27.5, "straight out of the circle it would stand behind our goal line: " + plain);
        Vector2 a = r.allowed(keeper, F);
        assertEquals(-27.2, a.x(), 1e-9, "0.3 m inside the goal line");
        assertEquals(3 - Math.sqrt(6.5 * 6.5 - 3.2 * 3.2), a.y(), 1e-9, "where the line leaves the 6.5 m circle, on the keeper's side");
        assertEquals(6.5, a.distanceTo(ball), 1e-9);
        Vector2 onField = new Vector2(-10, 5);
        assertEquals(onField, r.allowed(onField, F));
    }

    @Test
    void fieldPlayersPlacesStayOutOfOurGoalieArea() {
        // our goalie area: x <= -23.5, |y| <= 3.65; grown by 1 m: x < -22.5, |y| < 4.65
        assertEquals(new Vector2(-22.5, 1), MjSetPiece.outOfOurGoalieArea(new Vector2(-23, 1), F, 1.0), "nearest edge: the front");
        assertEquals(new Vector2(-26, 4.65), MjSetPiece.outOfOurGoalieArea(new Vector2(-26, 4), F, 1.0), "nearest edge: the side");
        assertEquals(new Vector2(-26, -4.65), MjSetPiece.outOfOurGoalieArea(new Vector2(-26, -4), F, 1.0));
        Vector2 out = new Vector2(-20, 0);
        assertSame(out, MjSetPiece.outOfOurGoalieArea(out, F, 1.0));
        assertEquals(new Vector2(25, 0), MjSetPiece.outOfOurGoalieArea(new Vector2(25, 0), F, 1.0), "theirs is not ours");
    }

    @Test
    void keepingOffTheBallIsACircleOfItsOwn() {
        MjSetPiece r = MjSetPiece.around(new Vector2(3, 0), 1.0, 0);
        assertEquals(new Vector2(2, 0), r.allowed(new Vector2(2.5, 0)));
        assertTrue(r.forbidden(new Vector2(3.5, 0)));
        assertFalse(r.forbidden(new Vector2(4.1, 0)));
    }
}

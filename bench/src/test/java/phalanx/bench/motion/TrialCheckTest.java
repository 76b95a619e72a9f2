package phalanx.bench.motion;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Issue 22: a trial that measured nothing says why, decided on values alone (no server). */
class TrialCheckTest {

    @Test
    void aRobotStandingWhereItWasMovedInPlayOnIsPlaced() {
        assertNull(TrialCheck.placement(0.03, 1.02, PlayMode.PLAY_ON, 25, 0.02));
    }

    @Test
    void placementFailuresNameTheirCause() {
        assertTrue(TrialCheck.placement(0.03, 1.02, PlayMode.PLAY_ON, 0, 0.02).contains("no monitor picture"));
        assertTrue(TrialCheck.placement(Double.NaN, 1.02, PlayMode.PLAY_ON, 50, 0.02).contains("no player 1 of team Left"));
        String far = TrialCheck.placement(2.5, 1.02, PlayMode.PLAY_ON, 50, 0.02);
        assertTrue(far.contains("trainer move had no effect") && far.contains("2.50 m"), far);
        // the agent's own game time went on: the (time 0) went to another server than our player's
        String clock = TrialCheck.placement(0.03, 301.4, PlayMode.PLAY_ON, 50, -300.4);
        assertTrue(clock.contains("did not reach our player") && clock.contains("301.40"), clock);
        String mode = TrialCheck.placement(0.03, 0, PlayMode.BEFORE_KICK_OFF, 50, 0.02);
        assertTrue(mode.contains("BeforeKickOff"), mode);
        assertTrue(TrialCheck.placement(0.03, Double.NaN, null, 50, Double.NaN).contains("play mode none"));
        // a server that does not wait for our player (agent-sync mode off, real time off) runs seconds ahead of it
        String racing = TrialCheck.placement(0.03, 3.56, PlayMode.PLAY_ON, 0, 2.5);
        assertTrue(racing.contains("2.50 s") && racing.contains("agent-sync"), racing);
    }

    @Test
    void aKickThatMovedTheBallMeasured() {
        // the committed strong kick on a fresh server: the foot's centre 9 cm from the ball's, the ball 10.9 m
        assertNull(TrialCheck.kick(0.004, 230, 0.45, 0.09, 10.9));
        // a miss that still nudged the ball: a (bad) result, not nothing
        assertNull(TrialCheck.kick(0.004, 230, 0.45, 0.12, 0.03));
    }

    @Test
    void theIssue22TrialsMeasuredNothing() {
        // what every trial of issue 22 showed: pictures that never changed (ball and robot still) or none at all
        assertTrue(TrialCheck.kick(0.004, 0, 0, Double.POSITIVE_INFINITY, 0).contains("no monitor picture"));
        assertTrue(TrialCheck.kick(0.0, 230, 0, 0.15, 0).contains("never moved while our player kicked"));
    }

    @Test
    void theBallThatNeverMovedSaysWhetherTheRobotReachedIt() {
        String far = TrialCheck.kick(0.004, 230, 0.40, 0.26, 0.002);
        assertTrue(far.startsWith("the ball never moved: the robot never reached it") && far.contains("0.26 m"), far);
        String near = TrialCheck.kick(0.004, 230, 0.40, 0.08, 0.002);
        assertTrue(near.startsWith("the ball never moved, though") && near.contains("0.08 m"), near);
    }

    @Test
    void aBallOffItsSpotOrMissingIsNoKick() {
        String off = TrialCheck.kick(3.0, 230, 0.45, 0.09, 10.9);
        assertTrue(off.contains("not on its spot") && off.contains("3.00 m"), off);
        assertEquals("no ball in the monitor's scene", TrialCheck.kick(Double.NaN, 230, 0.45, 0.09, 10.9));
    }

    @Test
    void aWalkOrTurnMustMoveTheRobot() {
        assertNull(TrialCheck.motion(500, 4.1));
        assertTrue(TrialCheck.motion(0, 4.1).contains("no monitor picture"));
        assertTrue(TrialCheck.motion(500, 0.0).contains("never moved"));
        assertTrue(TrialCheck.motion(500, Double.NaN).contains("never moved"));
    }

    @Test
    void aKickWatchSeesTravelReachAndTheBall() {
        List<double[]> start = List.of(new double[] {0, 0, 0.3}, new double[] {0.05, -0.05, 0.05});
        KickWatch w = new KickWatch(start, new double[] {0.2, -0.04, 0.042});
        w.see(start, new double[] {0.2, -0.04, 0.042});
        assertEquals(0, w.bodyTravel());
        assertEquals(0, w.ballTravel());
        // the foot swings to 5 cm behind the ball's centre, then the ball is gone 3 m
        w.see(List.of(new double[] {0, 0, 0.3}, new double[] {0.15, -0.04, 0.042}), new double[] {0.2, -0.04, 0.042});
        w.see(null, new double[] {3.2, -0.04, 0.042});
        assertEquals(0.10, w.bodyTravel(), 1e-3);
        assertEquals(0.05, w.closest(), 1e-9);
        assertEquals(3.0, w.ballTravel(), 1e-9);
        assertNull(TrialCheck.kick(0.0, 3, w.bodyTravel(), w.closest(), w.ballTravel()));
    }

    @Test
    void aKickWatchWithoutTheRobotSeesNoTravel() {
        KickWatch w = new KickWatch(null, new double[] {0, 0, 0.042});
        w.see(null, new double[] {0, 0, 0.042});
        assertEquals(0, w.bodyTravel());
        assertEquals(Double.POSITIVE_INFINITY, w.closest());
        assertTrue(TrialCheck.kick(0.0, 3, w.bodyTravel(), w.closest(), w.ballTravel()).contains("never moved while our player kicked"));
    }

    @Test
    void theTallyNamesFiguresWithoutAMeasuredTrial() {
        Tally t = new Tally();
        t.measured("kick");
        t.unmeasured("kick", "the ball never moved: x");
        t.unmeasured("strong_kick", "no monitor picture came during the kick");
        t.unmeasured("strong_kick", "no monitor picture came during the kick");
        t.unmeasured("strong_kick", "the ball never moved: y");
        assertEquals(List.of("kick", "strong_kick"), t.figures());
        assertEquals(List.of("strong_kick"), t.nothingMeasured());
        assertEquals(1, t.measuredCount("kick"));
        assertEquals(3, t.unmeasuredCount("strong_kick"));
        assertEquals(List.of("kick: 1 of 2 trials measured nothing: the ball never moved: x",
                        "strong_kick: 3 of 3 trials measured nothing: no monitor picture came during the kick (x2); the ball never moved: y"),
                t.lines());
    }

    @Test
    void aTallyOfMeasuredTrialsOnlyHasNothingToSay() {
        Tally t = new Tally();
        t.measured("walk");
        assertEquals(List.of(), t.nothingMeasured());
        assertEquals(List.of(), t.lines());
    }
}

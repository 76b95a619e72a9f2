package phalanx.agent.mj;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;
import static phalanx.agent.mj.MjBehaviourTest.at;

/** The double-touch rule (soccer_referee.py _check_fouls, agent_na_touch_ball) as one player keeps it, by hand. */
class MjTouchRuleTest {
    /** Player of the left team at (x, 0) facing +x, the ball d ahead, in mode, at t; then the rule's step. */
    private static void step(MjTouchRule rule, MjWorld w, double t, String mode, double x, double d, boolean kicking, boolean other) {
        w.update(at(t, mode, x, 0, 0, d));
        rule.update(w, kicking, other);
    }

    @Test
    void ourKickOffEndedByOurTouchBarsUsUntilAnotherPlayerIsAtTheBall() {
        MjTouchRule rule = new MjTouchRule();
        MjWorld w = new MjWorld("Phalanx");
        step(rule, w, 10, "KickOff_Left", -0.4, 0.4, false, false);
        step(rule, w, 12, "KickOff_Left", -0.4, 0.4, true, false);
        assertFalse(rule.barred(), "not before the touch");
        step(rule, w, 12.02, "PlayOn", -0.4, 0.4, true, false);
        assertTrue(rule.barred(), "PlayOn 2 s into our kick-off, we at the ball: our touch");
        step(rule, w, 14, "PlayOn", -0.4, 3, false, false);
        assertTrue(rule.barred(), "the ball rolled away: still ours to leave alone");
        step(rule, w, 15, "PlayOn", -0.4, 3, false, true);
        assertFalse(rule.barred(), "another player at the ball: free");
        assertEquals(1, rule.bars());
    }

    @Test
    void aPushOnTheWayEndsTheSetPieceAsMuchAsAKick() {
        for (String mode : new String[] {"KickIn_Left", "corner_kick_left", "free_kick_left", "direct_free_kick_left"}) {
            MjTouchRule rule = new MjTouchRule();
            MjWorld w = new MjWorld("Phalanx");
            step(rule, w, 10, mode, -5, 2, false, false);
            step(rule, w, 13, "PlayOn", -5, 0.5, false, false);   // walking up, not kicking yet
            assertTrue(rule.barred(), mode);
            step(rule, w, 14, "KickIn_Right", -5, 3, false, false);
            assertFalse(rule.barred(), mode + ": a new referee decision lifts it");
        }
    }

    @Test
    void noBarWhenItWasNotOursNotUsNotATouchOrAGoalKick() {
        String[][] cases = {
                {"KickOff_Right", "0.4", "false"},   // their kick-off
                {"KickOff_Left", "3", "false"},      // a team-mate took it: we are 3 m off and not kicking
                {"goal_kick_left", "0.4", "false"},  // a goal kick bars nobody
        };
        for (String[] c : cases) {
            MjTouchRule rule = new MjTouchRule();
            MjWorld w = new MjWorld("Phalanx");
            double d = Double.parseDouble(c[1]);
            step(rule, w, 10, c[0], -1, d, Boolean.parseBoolean(c[2]), false);
            step(rule, w, 12, "PlayOn", -1, d, false, false);
            assertFalse(rule.barred(), c[0] + " at " + d + " m");
        }
        MjTouchRule rule = new MjTouchRule();
        MjWorld w = new MjWorld("Phalanx");
        step(rule, w, 10, "KickOff_Left", -0.4, 0.4, false, false);
        step(rule, w, 25, "PlayOn", -0.4, 0.4, false, false);
        assertFalse(rule.barred(), "15 s without a touch: the referee's timeout, not our touch");
        MjTouchRule kicking = new MjTouchRule();
        MjWorld k = new MjWorld("Phalanx");
        step(kicking, k, 10, "KickOff_Left", -0.4, 1.5, true, false);
        step(kicking, k, 11, "PlayOn", -0.4, 1.5, true, false);
        assertTrue(kicking.barred(), "our kick playing when it turned PlayOn: our touch, wherever we think the ball is");
    }

    @Test
    void aRightSidePlayerReadsItsOwnModes() {
        MjTouchRule rule = new MjTouchRule();
        MjWorld w = new MjWorld("Other");   // at() names "Other" the right team
        step(rule, w, 10, "KickOff_Right", 0.4, 0.4, false, false);
        step(rule, w, 11, "PlayOn", 0.4, 0.4, false, false);
        assertTrue(rule.barred());
    }
}

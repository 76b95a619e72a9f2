package phalanx.motion.t1;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

/** The T1 gait blending a walk and a turn preset by the command (T1GaitConfig.Blend). */
class T1GaitBlendTest {
    private static final T1GaitConfig.Blend B = T1GaitConfig.Blend.agent();
    private static final T1GaitConfig STAND = T1GaitConfig.balanced();

    private static void assertSameCommands(List<JointCommand> a, List<JointCommand> b, String when) {
        assertEquals(a.size(), b.size(), when);
        for (int k = 0; k < a.size(); k++) {
            JointCommand x = a.get(k), y = b.get(k);
            assertEquals(x.actuator(), y.actuator(), when);
            // the IK iterates from its last solution, so the two gaits' angles agree to its tolerance, not bit for bit
            assertEquals(x.qDeg(), y.qDeg(), 1e-6, when + " " + x.actuator());
            assertEquals(x.dqDeg(), y.dqDeg(), 1e-4, when + " " + x.actuator());
            assertEquals(x.kp(), y.kp(), 1e-12, when);
            assertEquals(x.kd(), y.kd(), 1e-12, when);
        }
    }

    @Test
    void lerpIsEachEndAtZeroAndOneAndLinearBetween() {
        T1GaitConfig w = B.walk(), t = B.turn();
        assertEquals(w, w.lerp(t, 0));
        assertEquals(t, w.lerp(t, 1));
        T1GaitConfig h = w.lerp(t, 0.5);
        assertEquals((w.stepTime() + t.stepTime()) / 2, h.stepTime(), 1e-12);
        assertEquals((w.strideScale() + t.strideScale()) / 2, h.strideScale(), 1e-12);
        assertEquals(w.hipY(), h.hipY(), 0, "geometry is the same in both");
    }

    @Test
    void walkingStraightIsTheWalkPresetAndStandingTheStandConfig() {
        T1Gait blended = new T1Gait(B, STAND), walk = new T1Gait(B.walk());
        assertSameCommands(new T1Gait(STAND).stand(), blended.stand(), "stand");
        walk.stand();
        // after the first step (the blend moves the stance from the stand config's) both walk alike
        int first = (int) Math.round(B.walk().stepTime() / B.walk().dt()) + 1;
        for (int i = 0; i < 300; i++) {
            blended.feedback(0.01, -0.05, 0.1, -0.1);
            walk.feedback(0.01, -0.05, 0.1, -0.1);
            List<JointCommand> a = blended.next(0.6, 0, 0), b = walk.next(0.6, 0, 0);
            if (i > first) assertSameCommands(b, a, "walking, cycle " + i);
            assertEquals(0, blended.turnShare(), 0, "no turn: the walk preset");
        }
    }

    @Test
    void turningOnTheSpotIsTheTurnPreset() {
        T1Gait blended = new T1Gait(B, STAND), turn = new T1Gait(B.turn());
        blended.stand();
        turn.stand();
        int first = (int) Math.round(B.turn().stepTime() / B.turn().dt()) + 1;
        for (int i = 0; i < 300; i++) {
            List<JointCommand> a = blended.next(0, 0, 120), b = turn.next(0, 0, 120);
            if (i > first) {
                assertEquals(1, blended.turnShare(), 0, "turning on the spot: the turn preset");
                assertSameCommands(b, a, "turning, cycle " + i);
            }
        }
    }

    @Test
    void theShareMovesAtMostTheRateAndTurnsWaitForTheWalkToSlowDown() {
        T1Gait g = new T1Gait(B, STAND);
        g.stand();
        for (int i = 0; i < 300; i++) g.next(0.6, 0, 0);
        double last = g.turnShare(), dt = B.walk().dt();
        for (int i = 0; i < 400; i++) {
            g.next(0, 0, 120);
            double s = g.turnShare();
            assertTrue(Math.abs(s - last) <= B.ratePerS() * dt + 1e-9, "share step " + (s - last) + " at cycle " + i);
            last = s;
            // slowing down from 0.6 at 0.2 m/s/s takes 3 s: till it is under fullSpeed the turn stays small, so the share too
            if (i < 100) assertTrue(s < 0.4, "still walking fast at cycle " + i + ": share " + s);
        }
        assertEquals(1, g.turnShare(), 1e-9, "in the end on the spot: the turn preset");
    }

    @Test
    void allowedTurnFallsWithTheSpeed() {
        assertEquals(Math.max(B.walk().maxTurn(), B.turn().maxTurn()), B.allowedTurn(0), 1e-9);
        assertEquals(B.turnAtSpeed(), B.allowedTurn(B.fullSpeed()), 1e-9);
        assertEquals(B.turnAtSpeed(), B.allowedTurn(0.6), 1e-9);
        assertTrue(B.allowedTurn(B.fullSpeed() / 2) > B.turnAtSpeed());
    }

    /** Every command within robot.xml's ranges (T1GaitTest's table), switching between all kinds of commands. */
    @Test
    void everyCommandIsWithinTheJointRanges() {
        T1Gait g = new T1Gait(B, STAND);
        T1GaitTest.assertInRange(g.stand(), "stand");
        double[][] commands = {{0, 0, 0}, {0.6, 0, 0}, {2, 0, 0}, {0, 0, 120}, {0.6, 0, 120}, {-1, 0, 0}, {0, 0.3, 0},
                {0, -0.3, -200}, {0.6, 0.2, 60}, {0.6, 0, -35}, {0, 0, -120}, {0.2, 0.2, 120}};
        Random rnd = new Random(2);
        for (int round = 0; round < 3; round++)
            for (double[] cmd : commands) {
                for (int i = 0; i < 150; i++) {
                    g.feedback(0.3 * (rnd.nextDouble() - 0.5), 0.3 * (rnd.nextDouble() - 0.5), rnd.nextGaussian(), rnd.nextGaussian());
                    T1GaitTest.assertInRange(g.next(cmd[0], cmd[1], cmd[2]), "next(" + cmd[0] + ", " + cmd[1] + ", " + cmd[2] + ") cycle " + i);
                }
                if (rnd.nextInt(4) == 0) T1GaitTest.assertInRange(g.stand(), "stand");
            }
    }
}

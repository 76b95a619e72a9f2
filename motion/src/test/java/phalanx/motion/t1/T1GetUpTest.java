package phalanx.motion.t1;

import org.junit.jupiter.api.Test;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** T1GetUp's states: lying, the get-up motion, the recovery stand after it, and a fall in it. */
class T1GetUpTest {
    private static final double DT = 0.02;
    /** Face down: the torso's x axis points down (pitched +90 deg about y); upright; upright and pitched 10 deg forward. */
    private static final double[] FRONT = {Math.sqrt(0.5), 0, Math.sqrt(0.5), 0}, UPRIGHT = {1, 0, 0, 0},
            LEANING = {Math.cos(Math.toRadians(5)), 0, Math.sin(Math.toRadians(5)), 0};
    private static final double[] STILL = {0, 0, 0};

    private static T1GetUp getUp(double recoverS) throws Exception {
        T1Motion m = T1MotionLoader.parse("short", "short.motion", """
                #WEBOTS_MOTION,V1.0
                Left_Knee_Pitch,Right_Knee_Pitch
                00:00:100,bend,1.0,1.0
                """);
        return new T1GetUp(m, m, T1GetUp.Config.DEFAULT.withRecoverS(recoverS), T1GaitConfig.getUpRecovery());
    }

    /** Plays the 0.1 s motion from lying (5 cycles, the last with the robot upright); returns the time after it. */
    private static double playMotion(T1GetUp g) {
        assertNotNull(g.update(FRONT, STILL, a -> 0, 0), "lying still: the get-up starts at once");
        assertEquals(T1GetUp.State.GETTING_UP, g.state());
        for (int i = 1; i < 4; i++) assertNotNull(g.update(FRONT, STILL, a -> 0, i * DT));
        assertNotNull(g.update(UPRIGHT, STILL, a -> 0, 4 * DT), "the motion's last cycle");
        return 5 * DT;
    }

    @Test
    void afterTheMotionItHoldsTheRecoveryStandWithTorsoFeedbackThenHandsOver() throws Exception {
        T1GetUp g = getUp(0.5);
        double t = playMotion(g);
        assertEquals(T1GetUp.State.RECOVERING, g.state(), "up at the motion's end: the recovery stand");
        List<JointCommand> leaning = g.update(LEANING, STILL, a -> 0, t);
        assertEquals("recover", g.playing());
        T1Gait expected = new T1Gait(T1GaitConfig.getUpRecovery());
        expected.feedback(0, Math.toRadians(10), 0, 0);
        assertEquals(byActuator(expected.stand()), byActuator(leaning), "the recovery config's stand with the torso's 10 deg lean as feedback");
        T1Gait still = new T1Gait(T1GaitConfig.getUpRecovery());
        assertNotEquals(byActuator(still.stand()).get("lle5"), byActuator(leaning).get("lle5"), "the lean moves the ankles");
        int cycles = 0;
        for (t += DT; g.update(UPRIGHT, STILL, a -> 0, t) != null; t += DT) cycles++;
        assertEquals(0.5 / DT - 1, cycles, 1, "recoverS of commands after the motion");
        assertEquals(T1GetUp.State.UP, g.state());
        assertNull(g.update(UPRIGHT, STILL, a -> 0, t + DT), "then the caller's gait");
        assertEquals(1, g.getUps());
        assertEquals(0, g.retries());
    }

    @Test
    void aFallInTheRecoveryStandStartsTheNextGetUpAsARetry() throws Exception {
        T1GetUp g = getUp(1.0);
        double t = playMotion(g);
        assertNotNull(g.update(UPRIGHT, STILL, a -> 0, t));
        assertNotNull(g.update(FRONT, STILL, a -> 0, t + DT), "down again, lying still: the next get-up");
        assertEquals(T1GetUp.State.GETTING_UP, g.state());
        assertEquals(2, g.getUps());
        assertEquals(1, g.retries(), "the fall in the recovery stand made it a retry");
    }

    @Test
    void withoutRecoveryTheCallersGaitActsRightAfterTheMotion() throws Exception {
        T1GetUp g = getUp(0);
        double t = playMotion(g);
        assertEquals(T1GetUp.State.UP, g.state());
        assertNull(g.update(UPRIGHT, STILL, a -> 0, t));
    }

    @Test
    void inTheRiseTheTorsosPitchRateMovesTheAnklesAndHips() throws Exception {
        T1Motion m = T1MotionLoader.parse("rise", "rise.motion", """
                #WEBOTS_MOTION,V1.0
                Left_Ankle_Pitch,Right_Ankle_Pitch,Left_Hip_Pitch,Right_Hip_Pitch
                00:00:100,squat,-0.5,-0.5,-1.0,-1.0
                00:00:200,rise,-0.3,-0.3,-0.5,-0.5
                """);
        T1GetUp.Config c = T1GetUp.Config.DEFAULT.with("riseFrontS", 0.1).with("riseBackS", 0.5).with("riseAnkleRateGain", 0.05).with("riseHipRateGain", 0.02);
        T1GetUp g = new T1GetUp(m, m, c, T1GaitConfig.getUpRecovery());
        T1MotionPlayer plain = new T1MotionPlayer(DT, T1MotionPlayer.Gains.DEFAULT);
        plain.start(m, a -> 0);
        double[] forward = {0, Math.toDegrees(2.0), 0};   // pitching forward at 2 rad/s
        for (int i = 0; i < 10; i++) {
            Map<String, JointCommand> fb = byActuator(g.update(FRONT, i == 0 ? STILL : forward, a -> 0, i * DT)), ref = byActuator(plain.next());
            boolean rise = i >= 5;   // after the next() of cycle i, 0.2 - 0.02 (i + 1) s are left: under 0.1 s from cycle 5 on
            assertEquals(ref.get("lle5").qDeg() + (rise ? Math.toDegrees(0.05 * 2) : 0), fb.get("lle5").qDeg(), 1e-9, "cycle " + i + ": ankle toes down");
            assertEquals(ref.get("rle5").qDeg() + (rise ? Math.toDegrees(0.05 * 2) : 0), fb.get("rle5").qDeg(), 1e-9, "cycle " + i);
            assertEquals(ref.get("lle1").qDeg() + (rise ? Math.toDegrees(0.02 * 2) : 0), fb.get("lle1").qDeg(), 1e-9, "cycle " + i + ": hips open");
            assertEquals(ref.get("lle4").qDeg(), fb.get("lle4").qDeg(), 1e-9, "the knee as the motion has it");
            assertEquals(ref.get("lle5").dqDeg(), fb.get("lle5").dqDeg(), 1e-9, "the motion's velocity");
        }
        // face up: get_up_back's window (here all of it) and not get_up_front's
        T1Motion other = T1MotionLoader.parse("other", "other.motion", "#WEBOTS_MOTION,V1.0\nLeft_Ankle_Pitch\n00:00:200,p,0\n");
        T1GetUp sides = new T1GetUp(other, m, c.with("riseFrontS", 0).with("riseBackS", 1), T1GaitConfig.getUpRecovery());
        double[] faceUp = {Math.sqrt(0.5), 0, -Math.sqrt(0.5), 0};
        sides.update(faceUp, STILL, a -> 0, 0);
        assertEquals("rise", sides.playing());
        T1MotionPlayer back = new T1MotionPlayer(DT, T1MotionPlayer.Gains.DEFAULT);
        back.start(m, a -> 0);
        back.next();
        assertEquals(back.next().stream().filter(j -> j.actuator().equals("lle5")).findFirst().orElseThrow().qDeg() + Math.toDegrees(0.1),
                byActuator(sides.update(faceUp, forward, a -> 0, DT)).get("lle5").qDeg(), 1e-9, "the back get-up's rise window");
        // a fast fall forward: the correction is bounded (T1Gait.MAX_CORRECTION), and the joint's range holds
        T1GetUp fast = new T1GetUp(m, m, c.with("riseAnkleRateGain", 1.0), T1GaitConfig.getUpRecovery());
        Map<String, JointCommand> last = null;
        for (int i = 0; i < 10; i++) last = byActuator(fast.update(FRONT, i == 0 ? STILL : forward, a -> 0, i * DT));
        assertEquals(Math.toDegrees(-0.3 + T1Gait.MAX_CORRECTION), last.get("lle5").qDeg(), 1e-9);
        T1Motion toesUp = T1MotionLoader.parse("up", "up.motion", "#WEBOTS_MOTION,V1.0\nLeft_Ankle_Pitch\n00:00:020,p,0.3\n00:00:100,q,0.3\n");
        T1GetUp ranged = new T1GetUp(toesUp, toesUp, c.with("riseFrontS", 1).with("riseAnkleRateGain", 1.0), T1GaitConfig.getUpRecovery());
        ranged.update(FRONT, STILL, a -> 0, 0);
        assertEquals(Math.toDegrees(0.35), byActuator(ranged.update(FRONT, forward, a -> 0, DT)).get("lle5").qDeg(), 1e-9,
                "within the ankle's range (0.35 rad)");
    }

    @Test
    void refusesABadConfigWithItsField() {
        var unknown = assertThrows(IllegalArgumentException.class, () -> T1GetUp.Config.DEFAULT.with("riseGain", 1));
        assertTrue(unknown.getMessage().contains("riseGain") && unknown.getMessage().contains("riseAnkleRateGain"), unknown.getMessage());
        var nan = assertThrows(IllegalArgumentException.class, () -> T1GetUp.Config.DEFAULT.with("riseHipRateGain", Double.NaN));
        assertTrue(nan.getMessage().contains("riseHipRateGain"), nan.getMessage());
        var e = assertThrows(IllegalArgumentException.class, () -> T1GetUp.Config.DEFAULT.withRecoverS(-1));
        assertTrue(e.getMessage().contains("recoverS"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> T1GetUp.Config.DEFAULT.withRecoverS(Double.NaN));
        assertTrue(e.getMessage().contains("recoverS"), e.getMessage());
    }

    private static Map<String, JointCommand> byActuator(List<JointCommand> cmds) {
        Map<String, JointCommand> m = new HashMap<>();
        for (JointCommand c : cmds) assertNull(m.put(c.actuator(), c), "one command per actuator: " + c.actuator());
        return m;
    }
}

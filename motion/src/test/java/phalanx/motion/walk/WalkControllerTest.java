package phalanx.motion.walk;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.motion.MotionConfig;
import phalanx.motion.control.JointVelocities;
import phalanx.model.robot.NaoModel;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.*;

class WalkControllerTest {
    private static final Vector3 STILL = new Vector3(0, 0, 0), UPRIGHT = new Vector3(0, 0, 9.81);

    /** Readings of a type 0-3 robot (no toes) all at {@code deg}. */
    private static JointAngles all(double deg) {
        double[] d = new double[Joint.COUNT];
        Arrays.fill(d, deg);
        d[Joint.LLJ7.ordinal()] = Double.NaN;
        d[Joint.RLJ7.ordinal()] = Double.NaN;
        return new JointAngles(d);
    }

    private static WalkConfig noFeedback() {
        return WalkConfig.DEFAULT.with("gyroPitchGain", 0).with("gyroRollGain", 0).with("gyroYawGain", 0)
                .with("tiltPlaceForward", 0).with("tiltPlaceLeft", 0).with("tiltHipPitch", 0).with("servoGain", 1);
    }

    @Test
    void velocityIsTheRemainingErrorOverOneCycleMinusTheCommandOnItsWay() {
        WalkConfig c = noFeedback();
        WalkController w = new WalkController(c, 0, MotionConfig.DEFAULT);
        double[] target = new WalkGenerator(c, NaoModel.TYPE_0, 0.02).step(WalkVelocity.ZERO);
        // knee target about -60 deg from 0: far beyond one cycle at the cap, so the cap (6.1395 rad/s) applies
        JointVelocities v = w.step(all(0), STILL, UPRIGHT, WalkVelocity.ZERO);
        assertEquals(-6.1395, v.radPerSecond(Joint.LLJ4), 1e-12);
        assertFalse(v.has(Joint.LLJ7), "no toes on type 0: no command");
        // a joint 0.5 deg from its target with no command on its way: 0.5 deg / 0.02 s
        double[] reading = new double[Joint.COUNT];
        for (int i = 0; i < reading.length; i++) reading[i] = target[i] - 0.5;
        reading[Joint.LLJ7.ordinal()] = Double.NaN;
        reading[Joint.RLJ7.ordinal()] = Double.NaN;
        WalkController fresh = new WalkController(c, 0, MotionConfig.DEFAULT);
        JointVelocities u = fresh.step(new JointAngles(reading), STILL, UPRIGHT, WalkVelocity.ZERO);
        assertEquals(Math.toRadians(0.5) / 0.02, u.radPerSecond(Joint.RLJ3), 1e-9);
        // next cycle with the same reading: the 0.5 deg commanded is already on its way, so nothing more
        JointVelocities u2 = fresh.step(new JointAngles(reading), STILL, UPRIGHT, WalkVelocity.ZERO);
        assertEquals(0, u2.radPerSecond(Joint.RLJ3), 1e-9);
    }

    @Test
    void startingFromAKeyframePoseTheTargetsEaseFromThatPoseToTheGaitsOverTheGivenCycles() {
        WalkConfig c = noFeedback();
        MotionConfig noLatency = MotionConfig.DEFAULT.withLatencyCycles(0);   // velocity = (target - reading) / cycle
        double knee = new WalkGenerator(c, NaoModel.TYPE_0, 0.02).step(WalkVelocity.ZERO)[Joint.LLJ4.ordinal()];
        double[] d = new double[Joint.COUNT];
        Arrays.fill(d, Double.NaN);
        d[Joint.LLJ4.ordinal()] = knee - 10;   // a crouch 10 deg deeper than the walk's, as a kick leaves it
        JointAngles crouch = new JointAngles(d);
        // without the ease the knee goes for its target at the cap (10 deg in a cycle is 8.7 rad/s)
        assertEquals(6.1395, new WalkController(c, 0, noLatency).step(crouch, STILL, UPRIGHT, WalkVelocity.ZERO).radPerSecond(Joint.LLJ4), 1e-9);
        WalkController w = new WalkController(c, 0, noLatency);
        w.startFrom(crouch, 20);
        double[] v = new double[21];
        for (int k = 1; k <= 20; k++) v[k] = w.step(crouch, STILL, UPRIGHT, WalkVelocity.ZERO).radPerSecond(Joint.LLJ4);
        // cosine ramp: share 0.5 - 0.5 cos(pi k / 20) of the 10 deg after k cycles
        assertEquals(Math.toRadians(10 * (0.5 - 0.5 * Math.cos(Math.PI / 20))) / 0.02, v[1], 1e-9);
        assertEquals(Math.toRadians(5) / 0.02, v[10], 1e-9);
        assertEquals(6.1395, v[20], 1e-9, "at the end the gait's own target, capped as before");
        for (int k = 2; k <= 20; k++) assertTrue(v[k] >= v[k - 1], "the ramp only rises: cycle " + k);
    }

    @Test
    void typeTwoAnkleRollIsCappedAtItsSlowerSpeed() {
        assertEquals(3.47234, WalkController.speedCap(2, Joint.LLJ6, 6.1395), 0);
        assertEquals(6.1395, WalkController.speedCap(2, Joint.RLJ5, 6.1395), 0); // the faster ankle pitch is not used
        assertEquals(6.1395, WalkController.speedCap(0, Joint.LLJ6, 6.1395), 0);
        WalkController w = new WalkController(noFeedback(), 2, MotionConfig.DEFAULT);
        double[] d = new double[Joint.COUNT];
        d[Joint.LLJ6.ordinal()] = 30; // far from its 0 target
        d[Joint.LLJ7.ordinal()] = Double.NaN;
        d[Joint.RLJ7.ordinal()] = Double.NaN;
        assertEquals(-3.47234, w.step(new JointAngles(d), STILL, UPRIGHT, WalkVelocity.ZERO).radPerSecond(Joint.LLJ6), 1e-12);
    }

    @Test
    void gyroPitchMovesBothAnklesByItsGain() {
        WalkConfig c = noFeedback().with("gyroPitchGain", 0.02);
        WalkController plain = new WalkController(noFeedback(), 0, MotionConfig.DEFAULT);
        WalkController fed = new WalkController(c, 0, MotionConfig.DEFAULT);
        double[] d = new WalkGenerator(noFeedback(), NaoModel.TYPE_0, 0.02).step(WalkVelocity.ZERO); // at the standing pose
        d[Joint.LLJ7.ordinal()] = Double.NaN;
        d[Joint.RLJ7.ordinal()] = Double.NaN;
        JointAngles at = new JointAngles(d);
        Vector3 gyro = new Vector3(50, 0, 0); // pitching up (backward) at 50 deg/s
        double a = plain.step(at, gyro, UPRIGHT, WalkVelocity.ZERO).radPerSecond(Joint.LLJ5);
        double b = fed.step(at, gyro, UPRIGHT, WalkVelocity.ZERO).radPerSecond(Joint.LLJ5);
        // 0.02 · 50 = 1 deg more ankle target, over one cycle
        assertEquals(Math.toRadians(1) / 0.02, b - a, 1e-9);
    }

    @Test
    void tiltEstimateFollowsTheAccelerometer() {
        WalkController w = new WalkController(noFeedback(), 0, MotionConfig.DEFAULT);
        // leaning 10 deg forward: gravity's reaction has a backward (-y) component in the torso frame
        Vector3 acc = new Vector3(0, -9.81 * Math.sin(Math.toRadians(10)), 9.81 * Math.cos(Math.toRadians(10)));
        for (int i = 0; i < 500; i++) w.step(all(0), STILL, acc, WalkVelocity.ZERO);
        assertEquals(10, w.pitchForward(), 0.01);
        assertEquals(0, w.rollRight(), 1e-9);
    }

    @Test
    void odometryIsTheGeneratorsCommandedMotion() {
        WalkController w = new WalkController(noFeedback(), 0, MotionConfig.DEFAULT);
        for (int i = 0; i < 100; i++) w.step(all(0), STILL, UPRIGHT, new WalkVelocity(0.3, 0, 0));
        assertEquals(0.3, w.velocity().forward(), 1e-12);
        assertEquals(0.3 * 0.02 * WalkConfig.DEFAULT.odometryForward(), w.odometry().forward(), 1e-12);
        assertTrue(w.walking());
    }

    @Test
    void missingGyroOrAccelerometerIsNoProblem() {
        WalkController w = new WalkController(WalkConfig.DEFAULT, 4, MotionConfig.DEFAULT);
        double[] d = new double[Joint.COUNT]; // type 4 has toes
        JointVelocities v = w.step(new JointAngles(d), null, null, new WalkVelocity(0.5, 0, 0));
        assertTrue(v.has(Joint.LLJ7));
        assertTrue(Double.isFinite(v.radPerSecond(Joint.LLJ3)));
    }

    @Test
    void aMessageWithoutJointsOrRequestGivesNoCommandsAndNoCrash() {
        WalkController w = new WalkController(WalkConfig.DEFAULT, 0, MotionConfig.DEFAULT);
        JointVelocities v = w.step(null, null, null, null);
        for (Joint j : Joint.values()) assertFalse(v.has(j), j + " got a command without a reading");
        assertFalse(w.walking());
    }
}

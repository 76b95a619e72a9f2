package phalanx.motion.kinematics;

import phalanx.model.robot.CameraHeight;
import phalanx.model.robot.NaoModel;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

import static org.junit.jupiter.api.Assertions.*;

class KinematicsTest {
    @Test
    void standingHeightsMatchTheRecordedTorsoHeights() {
        // recordings README: 0.3839 (types 0, 2, 4), 0.4205 (type 1), 0.4396 (type 3); the feet sink ~1 mm.
        assertEquals(0.3839, NaoModel.ofType(0).standingTorsoHeight(), 0.002);
        assertEquals(0.3839, NaoModel.ofType(4).standingTorsoHeight(), 0.002);
        assertEquals(0.4205, NaoModel.ofType(1).standingTorsoHeight(), 0.002);
        assertEquals(0.4396, NaoModel.ofType(3).standingTorsoHeight(), 0.002);
        assertThrows(IllegalArgumentException.class, () -> NaoModel.ofType(5));
    }

    @Test
    void straightLegNeedsNoBending() {
        LegIk.LegAngles q = LegIk.solve(NaoModel.TYPE_0, 0, 0, 0.22);
        assertEquals(0, q.hipPitch(), 1e-5);
        assertEquals(0, q.knee(), 1e-5);
        assertEquals(0, q.anklePitch(), 1e-5);
        assertEquals(0, q.hipRoll(), 1e-9);
    }

    @Test
    void equalSegmentsCrouchSymmetrically() {
        // Thigh = shank = 0.1 and the ankle 0.1 m straight below: an equilateral triangle,
        // so the thigh leans 60 deg forward, the knee bends -120 and the ankle lifts the toes 60.
        NaoModel g = new NaoModel(0, 0.1, 0.1, 0.055); // the fixed hip and sole offsets are the Nao's
        LegIk.LegAngles q = LegIk.solve(g, 0, 0, 0.1);
        assertEquals(60, q.hipPitch(), 1e-5);
        assertEquals(-120, q.knee(), 1e-9);
        assertEquals(60, q.anklePitch(), 1e-9);
    }

    @Test
    void inverseThenForwardGivesTheTargetBack() {
        for (int type : new int[] {0, 1, 3}) {
            NaoModel g = NaoModel.ofType(type);
            double[][] targets = {{0.04, 0.02, 0.18}, {-0.05, -0.03, 0.19}, {0.0, 0.0, 0.15}, {0.06, 0.0, 0.17}};
            for (double[] t : targets) {
                double[] back = LegIk.ankle(g, LegIk.solve(g, t[0], t[1], t[2]));
                assertArrayEquals(t, back, 1e-9, "type " + type);
            }
        }
    }

    @Test
    void footStaysParallelToTheTorso() {
        LegIk.LegAngles q = LegIk.solve(NaoModel.TYPE_0, 0.03, 0.02, 0.18);
        assertEquals(0, q.hipPitch() + q.knee() + q.anklePitch(), 1e-9);
        assertEquals(0, q.hipRoll() + q.ankleRoll(), 1e-9);
        assertTrue(q.hipRoll() > 0, "a foot to the left needs a positive hip roll");
    }

    @Test
    void cameraHeightStandingAndCrouched() {
        double[] d = new double[Joint.COUNT];
        JointAngles standing = new JointAngles(d);
        // Standing: sole 0.05 + 0.10 + 0.12 + 0.115 + 0.155 (M1: head at 0.5379 over a torso at 0.3829).
        assertEquals(0.54, CameraHeight.of(NaoModel.TYPE_0, standing), 1e-12);
        // Crouch hip 30, knee -60, ankle 30: the legs' vertical parts shrink by cos 30, the torso stays upright.
        d[Joint.LLJ3.ordinal()] = 30; d[Joint.LLJ4.ordinal()] = -60; d[Joint.LLJ5.ordinal()] = 30;
        d[Joint.RLJ3.ordinal()] = 30; d[Joint.RLJ4.ordinal()] = -60; d[Joint.RLJ5.ordinal()] = 30;
        double expected = 0.05 + 0.22 * Math.cos(Math.toRadians(30)) + 0.27;
        assertEquals(expected, CameraHeight.of(NaoModel.TYPE_0, new JointAngles(d)), 1e-12);
        // 4.6: the ground distance of a ball 1.0 m from a camera 0.6 m up is 0.8 m.
        assertEquals(0.8, CameraHeight.groundDistance(1.0, 0.6), 1e-12);
        assertEquals(0.0, CameraHeight.groundDistance(0.3, 0.5));
    }
}

package phalanx.motion.kinematics;

import phalanx.model.robot.NaoModel;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class FootPoseIkTest {
    private static final NaoModel G = NaoModel.TYPE_0; // thigh 0.12, shank 0.10

    @Test
    void straightLegBelowTheHipIsAllZero() {
        for (boolean left : new boolean[] {true, false}) {
            FootPoseIk.Angles q = FootPoseIk.solve(G, left, 0, 0, -0.22, 0, 0);
            assertEquals(0, q.yawPitch(), 1e-6);
            assertEquals(0, q.hipRoll(), 1e-6);
            // the solver keeps the leg 1 nm short of stretched (a singular pose): about 0.01 deg of bend
            assertEquals(0, q.hipPitch(), 0.02);
            assertEquals(0, q.knee(), 0.02);
            assertEquals(0, q.anklePitch(), 0.02);
            assertEquals(0, q.ankleRoll(), 1e-6);
        }
    }

    @Test
    void crouchByTheLawOfCosines() {
        // ankle 0.20 m below the hip: cos(inner knee) = (0.12² + 0.10² - 0.20²) / (2·0.12·0.10) = -0.65,
        // knee = -(180 - 130.54) = -49.46; hip = acos((0.12² + 0.20² - 0.10²) / (2·0.12·0.20)) = acos(0.925) = 22.33;
        // the flat foot needs ankle = -(hip + knee) = 27.13.
        FootPoseIk.Angles q = FootPoseIk.solve(G, true, 0, 0, -0.20, 0, 0);
        assertEquals(-49.46, q.knee(), 0.01);
        assertEquals(22.33, q.hipPitch(), 0.01);
        assertEquals(27.13, q.anklePitch(), 0.01);
        assertEquals(0, q.yawPitch(), 1e-6);
    }

    @Test
    void withoutYawItAgreesWithThePlanarLegIk() {
        // LegIk: (forward, left, down) from the hip; here x is right, so left = -x
        double[][] targets = {{0.03, 0.01, 0.19}, {-0.04, -0.02, 0.2}, {0.05, 0.0, 0.17}};
        for (double[] t : targets) {
            LegIk.LegAngles p = LegIk.solve(G, t[0], t[1], t[2]);
            FootPoseIk.Angles q = FootPoseIk.solve(G, true, -t[1], t[0], -t[2], 0, 0);
            assertEquals(p.hipRoll(), q.hipRoll(), 1e-6);
            assertEquals(p.hipPitch(), q.hipPitch(), 1e-6);
            assertEquals(p.knee(), q.knee(), 1e-6);
            assertEquals(p.anklePitch(), q.anklePitch(), 1e-6);
            assertEquals(p.ankleRoll(), q.ankleRoll(), 1e-6);
        }
    }

    @Test
    void roundTripThroughTheForwardKinematics() {
        for (boolean left : new boolean[] {true, false}) {
            for (double yaw : new double[] {0, 10, 25, 40}) {
                double outward = left ? yaw : -yaw;
                for (double pitch : new double[] {0, 8}) {
                    double x = left ? 0.012 : -0.008, y = 0.035, z = -0.185;
                    FootPoseIk.Angles q = FootPoseIk.solve(G, left, x, y, z, outward, pitch);
                    double[] f = FootPoseIk.forward(G, left, q);
                    assertEquals(x, f[0], 1e-9);
                    assertEquals(y, f[1], 1e-9);
                    assertEquals(z, f[2], 1e-9);
                    double[] want = FootPoseIk.footRotation(outward, pitch);
                    for (int i = 0; i < 9; i++) assertEquals(want[i], f[3 + i], 1e-9, "rotation element " + i);
                    // turning a foot outward needs a negative yaw-pitch, inside the joint's range [-90, 1]
                    if (yaw > 0) assertTrue(q.yawPitch() < 0 && q.yawPitch() > -90, "yaw-pitch " + q.yawPitch());
                }
            }
        }
    }

    @Test
    void outOfReachIsPulledInToAStretchedLeg() {
        FootPoseIk.Angles q = FootPoseIk.solve(G, false, 0, 0, -0.5, 0, 0);
        assertEquals(0, q.knee(), 0.02);
        double[] f = FootPoseIk.forward(G, false, q);
        assertEquals(-0.22, f[2], 1e-6);
    }
}

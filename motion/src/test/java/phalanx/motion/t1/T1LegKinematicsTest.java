package phalanx.motion.t1;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class T1LegKinematicsTest {
    private static final T1GaitConfig C = T1GaitConfig.defaults();

    @Test
    void straightLegMatchesTheSumOfTheXmlOffsets() {
        // robot.xml, torso to foot_link: Waist (0.0625, 0, -0.1155), hip (0, 0.106, 0), roll (0, 0, -0.02),
        // yaw (0, 0, -0.081854), knee (-0.014, 0, -0.134), ankle (0, 0, -0.28), foot (0, 0.00025, -0.012)
        double[] p = new T1LegKinematics(C, true).footPosition(new double[6]);
        assertArrayEquals(new double[]{0.0485, 0.10625, -0.643354}, p, 1e-9);
        double[] r = new T1LegKinematics(C, false).footPosition(new double[6]);
        assertArrayEquals(new double[]{0.0485, -0.10625, -0.643354}, r, 1e-9);
    }

    @Test
    void kneeBendMovesTheFootBackAndUp() {
        // 90 deg knee: the shank and foot (0.292 m) point backwards from the knee at z = -0.1155-0.02-0.081854-0.134
        double[] q = {0, 0, 0, Math.PI / 2, 0, 0};
        double[] p = new T1LegKinematics(C, true).footPosition(q);
        assertEquals(0.0485 - 0.292, p[0], 1e-9);
        assertEquals(-0.351354, p[2], 1e-9);
    }

    @Test
    void inverseThenForwardIsWithinAMillimetre() {
        Random rnd = new Random(7);
        for (boolean left : new boolean[]{true, false}) {
            T1LegKinematics k = new T1LegKinematics(C, left);
            double side = left ? 1 : -1;
            double[] q = {-0.3, 0, 0, 0.6, -0.3, 0};
            for (int i = 0; i < 300; i++) {
                // the gait's workspace: up to 7 cm ahead / behind, 3 cm sideways of the hip, 6 deg of yaw, a 7 cm high band of crouch
                double x = C.footX() + 0.14 * (rnd.nextDouble() - 0.5);
                double y = side * C.hipY() + 0.06 * (rnd.nextDouble() - 0.5);
                double z = -0.62 + 0.07 * rnd.nextDouble();
                double yaw = 0.2 * (rnd.nextDouble() - 0.5);
                double err = k.inverse(x, y, z, yaw, q);
                double[] t = k.forward(q, null, null);
                double d = Math.sqrt(Math.pow(t[3] - x, 2) + Math.pow(t[7] - y, 2) + Math.pow(t[11] - z, 2));
                assertTrue(d < 1e-3, "target " + x + ", " + y + ", " + z + " missed by " + d + " (yaw " + yaw + ")");
                assertEquals(d, err, 1e-3);
                // the sole is level (the foot's z axis up) and turned by yaw
                assertEquals(1, t[10], 1e-4, "sole level");
                assertEquals(yaw, Math.atan2(t[4], t[0]), 1e-3, "foot yaw");
            }
        }
    }
}

package phalanx.motion.t1;

import org.junit.jupiter.api.Test;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class T1GaitTest {
    private static final T1GaitConfig C = T1GaitConfig.defaults();

    /** A gait whose torso is at the wanted attitude (so the feedback adds nothing). */
    private static T1Gait upright() {
        T1Gait g = new T1Gait(C);
        g.feedback(0, Math.toRadians(C.torsoPitchDeg()), 0, 0);
        return g;
    }

    /** Joint ranges in degrees from rcsssmj's robots/T1/robot.xml (radians there), by actuator. */
    private static final Map<String, double[]> RANGE_RAD = new HashMap<>();

    static {
        String[][] legs = {{"1", "-1.8", "1.57", "-1.8", "1.57"}, {"2", "-0.2", "1.57", "-1.57", "0.2"}, {"3", "-1", "1", "-1", "1"},
                {"4", "0", "2.34", "0", "2.34"}, {"5", "-0.87", "0.35", "-0.87", "0.35"}, {"6", "-0.44", "0.44", "-0.44", "0.44"}};
        for (String[] j : legs) {
            RANGE_RAD.put("lle" + j[0], new double[]{Double.parseDouble(j[1]), Double.parseDouble(j[2])});
            RANGE_RAD.put("rle" + j[0], new double[]{Double.parseDouble(j[3]), Double.parseDouble(j[4])});
        }
        RANGE_RAD.put("he1", new double[]{-1.57, 1.57});
        RANGE_RAD.put("he2", new double[]{-0.35, 1.22});
        RANGE_RAD.put("lae1", new double[]{-3.31, 1.22});
        RANGE_RAD.put("rae1", new double[]{-3.31, 1.22});
        RANGE_RAD.put("lae2", new double[]{-1.74, 1.57});
        RANGE_RAD.put("rae2", new double[]{-1.57, 1.74});
        RANGE_RAD.put("lae3", new double[]{-2.27, 2.27});
        RANGE_RAD.put("rae3", new double[]{-2.27, 2.27});
        RANGE_RAD.put("lae4", new double[]{-2.44, 0});
        RANGE_RAD.put("rae4", new double[]{0, 2.44});
        RANGE_RAD.put("te1", new double[]{-1.57, 1.57});
    }

    private static Map<String, JointCommand> byName(List<JointCommand> cmds) {
        Map<String, JointCommand> m = new HashMap<>();
        for (JointCommand c : cmds) assertNull(m.put(c.actuator(), c), "one command per actuator: " + c.actuator());
        return m;
    }

    static void assertInRange(List<JointCommand> cmds, String when) {
        assertEquals(23, cmds.size(), "all 23 T1 actuators");
        for (JointCommand c : cmds) {
            double[] r = RANGE_RAD.get(c.actuator());
            assertNotNull(r, c.actuator());
            double q = Math.toRadians(c.qDeg());
            assertTrue(q >= r[0] - 1e-9 && q <= r[1] + 1e-9, when + ": " + c + " outside " + r[0] + ".." + r[1] + " rad");
            assertTrue(c.kp() > 0 && c.kd() >= 0 && Double.isFinite(c.dqDeg()), when + ": " + c);
        }
    }

    @Test
    void standIsMirrorSymmetric() {
        Map<String, JointCommand> m = byName(new T1Gait(C).stand());
        for (int k = 1; k <= 6; k++) {
            double l = m.get("lle" + k).qDeg(), r = m.get("rle" + k).qDeg();
            // pitch joints (1, 4, 5) equal; roll and yaw joints (2, 3, 6) mirrored
            if (k == 1 || k == 4 || k == 5) assertEquals(l, r, 1e-6, "lle" + k + " / rle" + k);
            else assertEquals(l, -r, 1e-6, "lle" + k + " / rle" + k);
            assertEquals(m.get("lle" + k).kp(), m.get("rle" + k).kp());
        }
        assertEquals(m.get("lae2").qDeg(), -m.get("rae2").qDeg(), 1e-9);
        // a crouch: knees bent, hips and ankles pitched the other way
        assertTrue(m.get("lle4").qDeg() > 20, "knee bent");
        assertTrue(m.get("lle1").qDeg() < 0 && m.get("lle5").qDeg() < 0);
    }

    @Test
    void standPlacesTheFeetAtTheConfiguredStance() {
        Map<String, JointCommand> m = byName(upright().stand());
        double[] q = new double[6];
        for (int k = 0; k < 6; k++) q[k] = Math.toRadians(m.get("lle" + (k + 1)).qDeg());
        double[] p = new T1LegKinematics(C, true).footPosition(q);
        assertEquals(C.footX(), p[0], 1e-3);
        assertEquals(C.footY(), p[1], 1e-3);
        assertEquals(C.footZ(), p[2], 1e-3);
    }

    @Test
    void everyCommandIsWithinTheJointRanges() {
        T1Gait g = new T1Gait(C);
        assertInRange(g.stand(), "stand");
        double[][] commands = {{0, 0, 0}, {0.8, 0, 0}, {2, 0, 0}, {-1, 0, 0}, {0, 0.3, 0}, {0, -0.3, 0}, {0, 0, 90}, {0, 0, -200}, {0.6, 0.2, 60}};
        Random rnd = new Random(1);
        for (double[] cmd : commands) {
            for (int i = 0; i < 200; i++) {
                g.feedback(0.3 * (rnd.nextDouble() - 0.5), 0.3 * (rnd.nextDouble() - 0.5), rnd.nextGaussian(), rnd.nextGaussian());
                assertInRange(g.next(cmd[0], cmd[1], cmd[2]), "next(" + cmd[0] + ", " + cmd[1] + ", " + cmd[2] + ") cycle " + i);
            }
        }
    }

    @Test
    void atZeroSpeedTheFeetReturnToStance() {
        T1Gait g = upright();
        g.stand();
        for (int i = 0; i < 150; i++) g.next(0.6, 0.1, 40);
        double[] moving = g.footOffsets();
        assertTrue(Math.abs(moving[0]) + Math.abs(moving[3]) > 0.02, "walking moves the feet");
        for (int i = 0; i < 200; i++) g.next(0, 0, 0);
        // at the end of a step (the swing foot down) both feet are at their stance position, x, y and yaw
        boolean support = g.leftSupport();
        int guard = 0;
        while (g.leftSupport() == support && guard++ < 100) g.next(0, 0, 0);
        double[] f = g.footOffsets();
        for (double v : f) assertEquals(0, v, 1e-3, java.util.Arrays.toString(f));
        assertEquals(0, g.lifts()[0] + g.lifts()[1], 0.01, "a step begins with the feet (almost) down");
    }

    @Test
    void aSwingFootLiftsAndLandsWithinAStep() {
        T1Gait g = new T1Gait(C);
        g.stand();
        int n = (int) Math.round(C.stepTime() / C.dt());
        double maxLift = 0;
        for (int i = 0; i < n; i++) {
            g.next(0, 0, 0);
            maxLift = Math.max(maxLift, g.lifts()[1]);
            assertEquals(0, g.lifts()[0], 1e-12, "the support foot (left, first) stays down");
        }
        assertTrue(maxLift > 0.5 * C.lift(), "the swing foot lifts: " + maxLift);
    }
}

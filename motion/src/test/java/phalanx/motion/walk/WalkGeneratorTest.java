package phalanx.motion.walk;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.model.robot.NaoModel;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class WalkGeneratorTest {
    private static final double DT = 0.02;
    private static final NaoModel G = NaoModel.TYPE_0;

    /** A plain config for hand-checked numbers: no lean, no sway, leg height 0.20 m (0.20 / 0.22 of the leg). */
    private static WalkConfig plain() {
        return WalkConfig.DEFAULT.with("torsoLeanDeg", 0).with("swayAmplitude", 0).with("legExtension", 0.20 / 0.22)
                .with("footForward", 0).with("stanceWidth", 0).with("stepSeconds", 0.12).with("doubleSupport", 0.1)
                .with("maxForward", 0.8).with("maxLeft", 0.3).with("maxTurnDeg", 90).with("maxBackward", 0.4)
                .with("accelForward", 1.0).with("accelLeft", 1.0).with("accelTurnDeg", 200)
                .with("decelForward", 1.0).with("turnAtFullSpeedDeg", 90);   // no speed/turn coupling: see turnRateIsLimitedByTheWalksOwnForwardSpeed
    }

    @Test
    void zeroVelocityStandsStillInTheCrouch() {
        WalkGenerator w = new WalkGenerator(plain(), G, DT);
        double[] first = w.step(WalkVelocity.ZERO);
        for (int i = 0; i < 100; i++) assertArrayEquals(first, w.step(WalkVelocity.ZERO), 0.0);
        assertFalse(w.walking());
        assertEquals(Odometry.NONE, w.odometry());
        assertEquals(new FootTarget(0, 0.055, 0, 0), w.leftFoot());
        assertEquals(new FootTarget(0, -0.055, 0, 0), w.rightFoot());
        // ankle 0.20 m under each hip: knee -49.46, hip 22.33, ankle 27.13 (law of cosines, FootPoseIkTest)
        for (Joint[] leg : new Joint[][] {{Joint.LLJ1, Joint.LLJ2, Joint.LLJ3, Joint.LLJ4, Joint.LLJ5, Joint.LLJ6},
                                          {Joint.RLJ1, Joint.RLJ2, Joint.RLJ3, Joint.RLJ4, Joint.RLJ5, Joint.RLJ6}}) {
            assertEquals(0, first[leg[0].ordinal()], 1e-6);
            assertEquals(0, first[leg[1].ordinal()], 1e-6);
            assertEquals(22.33, first[leg[2].ordinal()], 0.01);
            assertEquals(-49.46, first[leg[3].ordinal()], 0.01);
            assertEquals(27.13, first[leg[4].ordinal()], 0.01);
            assertEquals(0, first[leg[5].ordinal()], 1e-6);
        }
    }

    @Test
    void requestsAreClampedToTheLimitsJointly() {
        WalkGenerator w = new WalkGenerator(plain(), G, DT);
        assertArrayEquals(new double[] {0.8, 0, 0}, w.limit(new WalkVelocity(3, 0, 0)), 1e-12);
        assertArrayEquals(new double[] {-0.4, 0, 0}, w.limit(new WalkVelocity(-3, 0, 0)), 1e-12);
        assertArrayEquals(new double[] {0, -0.3, 0}, w.limit(new WalkVelocity(0, -1, 0)), 1e-12);
        assertArrayEquals(new double[] {0, 0, 90}, w.limit(new WalkVelocity(0, 0, 500)), 1e-12);
        // full forward and full turn together: each scaled by 1/sqrt(2)
        double k = 1 / Math.sqrt(2);
        assertArrayEquals(new double[] {0.8 * k, 0, 90 * k}, w.limit(new WalkVelocity(0.8, 0, 90)), 1e-12);
        // a request inside the ellipsoid is kept
        assertArrayEquals(new double[] {0.4, 0.1, 20}, w.limit(new WalkVelocity(0.4, 0.1, 20)), 1e-12);
    }

    @Test
    void velocityRisesByTheAccelerationLimitPerCycle() {
        WalkGenerator w = new WalkGenerator(plain(), G, DT);
        for (int i = 1; i <= 10; i++) {
            w.step(new WalkVelocity(0.8, 0.3, 90));
            // the request is scaled into the ellipsoid (1/sqrt(3) each), then each axis rises by accel·0.02 per cycle
            assertEquals(Math.min(i * 0.02, 0.8 / Math.sqrt(3)), w.velocity().forward(), 1e-12);
            assertEquals(Math.min(i * 0.02, 0.3 / Math.sqrt(3)), w.velocity().left(), 1e-12);
            assertEquals(Math.min(i * 4.0, 90 / Math.sqrt(3)), w.velocity().turnDeg(), 1e-12);
        }
        Random r = new Random(3);
        WalkVelocity prev = w.velocity();
        for (int i = 0; i < 500; i++) {
            w.step(new WalkVelocity(r.nextDouble() * 2 - 1, r.nextDouble() - 0.5, r.nextDouble() * 400 - 200));
            WalkVelocity v = w.velocity();
            assertTrue(Math.abs(v.forward() - prev.forward()) <= 0.02 + 1e-12);
            assertTrue(Math.abs(v.left() - prev.left()) <= 0.02 + 1e-12);
            assertTrue(Math.abs(v.turnDeg() - prev.turnDeg()) <= 4 + 1e-12);
            assertTrue(v.forward() <= 0.8 && v.forward() >= -0.4 && Math.abs(v.left()) <= 0.3 && Math.abs(v.turnDeg()) <= 90);
            prev = v;
        }
    }

    @Test
    void turnRateIsLimitedByTheWalksOwnForwardSpeed() {
        // at 0.8 m/s only 10 deg/s; 90 deg/s standing; linear between: allowed = 90 - 80·vf/0.8
        WalkConfig c = plain().with("turnAtFullSpeedDeg", 10).with("decelForward", 2.0);
        WalkGenerator w = new WalkGenerator(c, G, DT);
        assertEquals(90, w.turnAllowed(0), 1e-12);
        assertEquals(50, w.turnAllowed(0.4), 1e-12);
        assertEquals(10, w.turnAllowed(0.8), 1e-12);
        assertEquals(90, w.turnAllowed(-0.2), 1e-12);        // stepping back: no coupling
        assertEquals(0.8, w.forwardAllowed(-10), 1e-12);
        assertEquals(0.4, w.forwardAllowed(50), 1e-12);
        assertEquals(0, w.forwardAllowed(90), 1e-12);
        for (int i = 0; i < 60; i++) w.step(new WalkVelocity(0.8, 0, 0));
        assertEquals(0.8, w.velocity().forward(), 1e-12);
        // a turn in place asked at full speed: forward drops by decelForward·0.02 = 0.04 per cycle,
        // the turn only grows as far as the forward speed of the cycle allows
        for (int i = 1; i <= 20; i++) {
            w.step(new WalkVelocity(0, 0, 90));
            double vf = Math.max(0, 0.8 - 0.04 * i);
            assertEquals(vf, w.velocity().forward(), 1e-9);
            assertTrue(Math.abs(w.velocity().turnDeg()) <= 90 - 100 * vf + 1e-9, "cycle " + i + ": " + w.velocity());
        }
        for (int i = 0; i < 25; i++) w.step(new WalkVelocity(0, 0, 90));
        assertEquals(new WalkVelocity(0, 0, 90), w.velocity());
        // full speed with a 50 deg/s lean: the ellipsoid makes it (0.8k, 50k), k = 1/sqrt(1 + (50/90)²);
        // the walk then goes at the speed where 50k deg/s is allowed
        double k = 1 / Math.sqrt(1 + Math.pow(50.0 / 90, 2)), vf = 0.8 * (90 - 50 * k) / 80;
        for (int i = 0; i < 100; i++) w.step(new WalkVelocity(0.8, 0, 50));
        assertEquals(vf, w.velocity().forward(), 1e-9);
        assertEquals(50 * k, w.velocity().turnDeg(), 1e-9);
        // slowing uses decelForward (2 m/s² = 0.04 per cycle), speeding up accelForward (0.02)
        w.step(new WalkVelocity(0.8, 0, 0));
        assertEquals(vf + 0.02, w.velocity().forward(), 1e-9);
        w.step(new WalkVelocity(0.1, 0, 0));
        assertEquals(vf - 0.02, w.velocity().forward(), 1e-9);
    }

    @Test
    void odometryIsTheCommandedMotionTimesTheMeasuredScale() {
        WalkConfig c = plain().with("odometryForward", 0.8).with("odometryTurn", 0.5);
        WalkGenerator w = new WalkGenerator(c, G, DT);
        double forward = 0, turn = 0;
        for (int i = 0; i < 100; i++) { // 0.5 m/s reached after 25 cycles; 20 deg/s after 5
            w.step(new WalkVelocity(0.5, 0, 20));
            forward += w.odometry().forward();
            turn += w.odometry().turnDeg();
        }
        // forward: ramp 0.02·(1+...+25)·0.02 = 0.13 m, then 75 cycles · 0.01 m = 0.75 m; ·0.8
        assertEquals((0.13 + 0.75) * 0.8, forward, 1e-9);
        // turn: ramp 4·(1+...+5)·0.02 = 1.2 deg, then 95 cycles · 0.4 deg = 38 deg; ·0.5
        assertEquals((1.2 + 38) * 0.5, turn, 1e-9);
        assertEquals(0.5 * 0.02 * 0.8, w.odometry().forward(), 1e-12);
    }

    @Test
    void theSwingFootLandsHalfTheStanceMotionAhead() {
        WalkGenerator w = new WalkGenerator(plain().with("swingLinear", 0).with("swingMatchGround", 0), G, DT);
        for (int i = 0; i < 200; i++) w.step(new WalkVelocity(0.5, 0, 0));
        // stance lasts 0.12 · 1.1 = 0.132 s, the body moves 0.066 m: a foot lands 0.033 m ahead of neutral
        // and leaves the ground 0.033 m behind it
        double maxAhead = -1, minBehind = 1;
        for (int i = 0; i < 60; i++) {
            w.step(new WalkVelocity(0.5, 0, 0));
            maxAhead = Math.max(maxAhead, w.leftFoot().forward());
            minBehind = Math.min(minBehind, w.leftFoot().forward());
        }
        assertEquals(0.033, maxAhead, 1e-3);
        assertEquals(-0.033, minBehind, 0.011); // lift-off falls between cycles: within one cycle's 0.01 m
    }

    @Test
    void footTargetsAndJointTargetsMoveWithoutJumps() {
        WalkGenerator w = new WalkGenerator(WalkConfig.DEFAULT, G, DT);
        Random r = new Random(7);
        FootTarget pl = w.leftFoot(), pr = w.rightFoot();
        double[] pq = w.targets();
        WalkVelocity req = WalkVelocity.ZERO;
        for (int i = 0; i < 3000; i++) {
            if (i % 100 == 0) req = new WalkVelocity(r.nextDouble() * 1.2 - 0.4, r.nextDouble() * 0.4 - 0.2, r.nextDouble() * 180 - 90);
            if (i % 700 > 600) req = WalkVelocity.ZERO;
            double[] q = w.step(req);
            for (FootTarget[] f : new FootTarget[][] {{pl, w.leftFoot()}, {pr, w.rightFoot()}}) {
                // the fastest thing is a swing: at most 0.07 m of stride in 5 cycles with the Hermite's overshoot
                assertTrue(Math.abs(f[1].forward() - f[0].forward()) < 0.03, "forward jump at cycle " + i);
                assertTrue(Math.abs(f[1].left() - f[0].left()) < 0.03, "sideways jump at cycle " + i);
                assertTrue(Math.abs(f[1].yawDeg() - f[0].yawDeg()) < 10, "yaw jump at cycle " + i);
                assertTrue(Math.abs(f[1].lift() - f[0].lift()) <= WalkConfig.DEFAULT.stepHeight() * 0.6, "lift jump at cycle " + i);
            }
            for (Joint j : Joint.values()) assertTrue(Math.abs(q[j.ordinal()] - pq[j.ordinal()]) < 25, j + " jumps at cycle " + i);
            pl = w.leftFoot();
            pr = w.rightFoot();
            pq = q;
        }
    }

    @Test
    void feetNeverCrossOrTouch() {
        WalkGenerator w = new WalkGenerator(WalkConfig.DEFAULT, G, DT);
        Random r = new Random(11);
        WalkVelocity req = WalkVelocity.ZERO;
        for (int i = 0; i < 4000; i++) {
            if (i % 80 == 0) req = new WalkVelocity(r.nextDouble() * 1.2 - 0.4, r.nextDouble() * 0.6 - 0.3, r.nextDouble() * 180 - 90);
            w.step(req);
            FootTarget l = w.leftFoot(), rt = w.rightFoot();
            assertTrue(l.left() > rt.left(), "left foot right of the right one at cycle " + i);
            assertFalse(overlap(l, rt), "feet overlap at cycle " + i + ": " + l + " " + rt);
            // each hip yaw-pitch can only turn its foot outward
            assertTrue(l.yawDeg() >= -1e-9 && rt.yawDeg() <= 1e-9, "inward yaw at cycle " + i);
        }
    }

    @Test
    void turningUsesOutwardYawAndTheJointRange() {
        WalkConfig c = WalkConfig.DEFAULT;
        WalkGenerator w = new WalkGenerator(c, G, DT);
        double maxLeftYaw = 0;
        for (int i = 0; i < 300; i++) {
            double[] q = w.step(new WalkVelocity(0, 0, 90));
            maxLeftYaw = Math.max(maxLeftYaw, w.leftFoot().yawDeg());
            // turning left the right foot trails: it lands straight and turns out while the body turns over it
            assertTrue(w.rightFoot().yawDeg() <= 0 && w.rightFoot().yawDeg() >= -c.maxFootYawDeg());
            assertTrue(w.leftFoot().yawDeg() >= 0 && w.leftFoot().yawDeg() <= c.maxFootYawDeg());
            assertTrue(q[Joint.LLJ1.ordinal()] <= 1 && q[Joint.RLJ1.ordinal()] <= 1);
        }
        // the leading foot turns out by the whole stance's turn: 90 deg/s · stepSeconds · (1 + doubleSupport)
        assertEquals(Math.min(c.maxFootYawDeg(), 90 * c.stepSeconds() * (1 + c.doubleSupport())), maxLeftYaw, 0.5);
    }

    @Test
    void aZeroRequestBringsTheFeetBackAndStops() {
        WalkGenerator w = new WalkGenerator(WalkConfig.DEFAULT, G, DT);
        for (int i = 0; i < 200; i++) w.step(new WalkVelocity(0.6, 0.1, 30));
        assertTrue(w.walking());
        int n = 0;
        while (w.walking() && n++ < 500) w.step(WalkVelocity.ZERO);
        assertFalse(w.walking(), "still walking 10 s after the stop request");
        WalkConfig c = WalkConfig.DEFAULT;
        double side = G.hipHalfWidth() + c.stanceWidth();
        assertEquals(new FootTarget(c.footForward(), side, 0, 0), w.leftFoot());
        assertEquals(new FootTarget(c.footForward(), -side, 0, 0), w.rightFoot());
        assertEquals(Odometry.NONE, w.step(WalkVelocity.ZERO) == null ? null : w.odometry());
    }

    /** Do the two foot soles (0.08 wide, heel 0.05 behind and toes 0.11 ahead of the ankle) overlap? Separating axes. */
    static boolean overlap(FootTarget a, FootTarget b) {
        double[][] pa = corners(a), pb = corners(b);
        for (double[][] poly : new double[][][] {pa, pb}) {
            for (int e = 0; e < 4; e++) {
                double ex = poly[(e + 1) % 4][0] - poly[e][0], ey = poly[(e + 1) % 4][1] - poly[e][1];
                double nx = -ey, ny = ex;
                double amin = Double.MAX_VALUE, amax = -Double.MAX_VALUE, bmin = Double.MAX_VALUE, bmax = -Double.MAX_VALUE;
                for (double[] p : pa) { double d = p[0] * nx + p[1] * ny; amin = Math.min(amin, d); amax = Math.max(amax, d); }
                for (double[] p : pb) { double d = p[0] * nx + p[1] * ny; bmin = Math.min(bmin, d); bmax = Math.max(bmax, d); }
                if (amax < bmin || bmax < amin) return false;
            }
        }
        return true;
    }

    private static double[][] corners(FootTarget f) {
        double a = Math.toRadians(f.yawDeg()), co = Math.cos(a), si = Math.sin(a);
        double[][] local = {{WalkGenerator.TOE, WalkGenerator.FOOT_HALF_WIDTH}, {WalkGenerator.TOE, -WalkGenerator.FOOT_HALF_WIDTH},
                            {-WalkGenerator.HEEL, -WalkGenerator.FOOT_HALF_WIDTH}, {-WalkGenerator.HEEL, WalkGenerator.FOOT_HALF_WIDTH}};
        double[][] out = new double[4][];
        for (int i = 0; i < 4; i++) out[i] = new double[] {f.forward() + co * local[i][0] - si * local[i][1], f.left() + si * local[i][0] + co * local[i][1]};
        return out;
    }

    @Test
    void theOverlapTestItselfSeesTouchingFeet() {
        assertTrue(overlap(new FootTarget(0, 0.03, 0, 0), new FootTarget(0, -0.03, 0, 0)));
        assertFalse(overlap(new FootTarget(0, 0.055, 0, 0), new FootTarget(0, -0.055, 0, 0)));
        assertTrue(overlap(new FootTarget(0, 0.045, 0, 40), new FootTarget(0, -0.045, 0, -40)), "yawed heels meet");
    }
}

package phalanx.motion.walk;

import phalanx.comm.perception.Joint;
import phalanx.motion.kinematics.FootPoseIk;
import phalanx.model.robot.JointLimits;
import phalanx.model.robot.NaoModel;

import java.util.Arrays;

/**
 * The omnidirectional gait: from a requested velocity (forward, left, turn) to foot targets and
 * joint angles, one cycle per call. Values in, values out: no clock, no socket.
 *
 * <p>The model. Each foot has a ground pose (forward, left, yaw) relative to the torso centre.
 * A step lasts {@link WalkConfig#stepSeconds()}: first a double-support share with both feet on
 * the ground, then one foot swings. A foot on the ground moves against the body's motion of the
 * cycle (velocity × cycle, as a rigid body: translated, then turned), so the feet never slide and
 * the body goes exactly as commanded. The swinging foot goes from where it lifted off to its
 * landing pose along a cosine ease, lifted by stepHeight·sin(πs). It lands where the body's motion
 * over its coming stance (duration T = step·(1 + doubleSupport)) brings it back through neutral:
 * half of that motion ahead forward; sideways and in yaw the leading foot (the one on the side the
 * robot moves or turns to) lands the whole motion out and the trailing one at neutral, so a foot
 * only ever moves outward of its neutral pose (feet never cross, and each hip yaw-pitch joint,
 * which can only turn its foot outward, has room). The torso sways over the stance foot with a
 * sine over each step. Speeds are clamped to the config's limits (jointly, as an ellipsoid) and
 * changed by at most the acceleration (deceleration) limits per cycle; the turn rate is further
 * limited by the walk's own forward speed ({@link WalkConfig#turnAtFullSpeedDeg()}).
 *
 * <p>Zero request: the walk keeps stepping until the velocity is zero and both feet are back at
 * neutral, then stands (no lift, no sway) until a non-zero request.
 *
 * <p>One instance per player; not thread-safe.
 */
public final class WalkGenerator {
    /** Foot size of the model (naoleg.rsg): width, and heel behind / toes ahead of the ankle. */
    static final double FOOT_HALF_WIDTH = 0.04, HEEL = 0.05, TOE = 0.11;
    /** Gap kept between each foot and the robot's centre line. */
    static final double CENTRE_MARGIN = 0.003;

    private final WalkConfig c;
    private final NaoModel g;
    private final double dt;

    private double vf, vl, vt;                                 // current velocity, m/s, m/s, deg/s
    private boolean walking;
    private boolean leftSwings = true;
    private double t;                                          // seconds into the current step
    private boolean swingStarted;
    private final double[] left = new double[3], right = new double[3];   // ground poses: forward, left, yaw deg
    private final double[] liftoff = new double[3];
    private double lift;                                      // the swing foot's lift
    private double sway;                                      // the torso's lateral shift (feet shift by -sway)
    private Odometry odometry = Odometry.NONE;
    private double placeForward, placeLeft;                  // balance corrections of the landing
    private final double[] targets = new double[Joint.COUNT];
    // scratch of step(), reused every cycle: the limited request and the landing pose
    private final double[] want = new double[3], land = new double[3], neutralPose = new double[3];
    private final FootPoseIk ik = new FootPoseIk();
    private static final Joint[] JOINTS = Joint.values();

    public WalkGenerator(WalkConfig config, NaoModel geometry, double cycleSeconds) {
        this.c = config;
        this.g = geometry;
        this.dt = cycleSeconds;
        neutral(true, left);
        neutral(false, right);
        computeTargets();
    }

    /** One cycle: advances the gait by the cycle and returns the joint targets (see {@link #targets()}). */
    public double[] step(WalkVelocity request) { return step(request, 0, 0); }

    /**
     * One cycle with a balance correction: the swinging foot lands {@code placeForward} metres
     * further ahead and {@code placeLeft} further left than the gait alone would put it (kept
     * within the feet's no-crossing bounds).
     */
    public double[] step(WalkVelocity request, double placeForward, double placeLeft) {
        return advance(request, placeForward, placeLeft).clone();
    }

    /**
     * {@link #step(WalkVelocity, double, double)} without the copy, for the {@link WalkController}:
     * the returned array is this generator's own, valid until the next call; read it, don't keep it.
     */
    double[] advance(WalkVelocity request, double placeForward, double placeLeft) {
        this.placeForward = placeForward;
        this.placeLeft = placeLeft;
        limit(request, want);
        if (!walking) {
            if (want[0] == 0 && want[1] == 0 && want[2] == 0) {
                odometry = Odometry.NONE;
                return targets;
            }
            walking = true;
            t = 0;
            swingStarted = false;
            // the leading foot first when moving sideways or turning
            leftSwings = want[1] != 0 ? want[1] > 0 : want[2] >= 0;
        }
        double wf = want[0] > 0 ? Math.min(want[0], forwardAllowed(want[2])) : want[0];
        boolean slowing = (vf > 0 && wf < vf) || (vf < 0 && wf > vf);
        vf += clampAbs(wf - vf, (slowing ? c.decelForward() : c.accelForward()) * dt);
        vl += clampAbs(want[1] - vl, c.accelLeft() * dt);
        vt += clampAbs(want[2] - vt, c.accelTurnDeg() * dt);
        double turnCap = turnAllowed(vf);
        vt = clampAbs(vt, turnCap);
        double df = vf * dt, dl = vl * dt, dTheta = vt * dt;
        odometry = new Odometry(df * c.odometryForward(), dl * c.odometryLeft(), dTheta * c.odometryTurn());

        double ts = c.stepSeconds(), ds = c.doubleSupport() * ts;
        t += dt;
        double[] swing = leftSwings ? left : right, stance = leftSwings ? right : left;
        carry(stance, df, dl, dTheta);
        if (t <= ds + 1e-9) {
            carry(swing, df, dl, dTheta);
            lift = 0;
        } else {
            if (!swingStarted) {
                swingStarted = true;
                carry(swing, df, dl, dTheta);   // this cycle's motion still happened on the ground
                System.arraycopy(swing, 0, liftoff, 0, 3);
            }
            double s = Math.min(1, (t - ds) / (ts - ds));
            landing(leftSwings, land);
            // cubic Hermite from lift-off to landing; end tangents follow the ground under the torso
            double swingTime = ts - ds, s2 = s * s, s3 = s2 * s;
            double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
            for (int k = 0; k < 3; k++) {
                double ground = k == 0 ? -vf : k == 1 ? -vl : -vt;
                double m = c.swingMatchGround() * ground * swingTime + c.swingLinear() * (land[k] - liftoff[k]);
                swing[k] = h00 * liftoff[k] + h10 * m + h01 * land[k] + h11 * m;
            }
            lift = c.stepHeight() * Math.pow(Math.sin(Math.PI * s), c.liftExponent());
        }
        keepApart(left, true);
        keepApart(right, false);
        sway = (leftSwings ? -1 : 1) * c.swayAmplitude() * Math.sin(Math.PI * (Math.min(t, ts) / ts + c.swayLead()));
        if (t >= ts - 1e-9) {
            t -= ts;
            leftSwings = !leftSwings;
            swingStarted = false;
            lift = 0;
            if (want[0] == 0 && want[1] == 0 && want[2] == 0 && vf == 0 && vl == 0 && vt == 0 && atNeutral()) {
                walking = false;
                sway = 0;
                t = 0;
                neutral(true, left);
                neutral(false, right);
            }
        }
        computeTargets();
        return targets;
    }

    /** Joint targets in degrees by {@link Joint#ordinal()}: legs (toes 0), arms, head 0. */
    public double[] targets() { return targets.clone(); }

    /** This cycle's motion as commanded (zero while standing). */
    public Odometry odometry() { return odometry; }

    /** The velocity now, after the limits. */
    public WalkVelocity velocity() { return new WalkVelocity(vf, vl, vt); }

    /** The turn rate now, deg/s (the third component of {@link #velocity()}, without the record). */
    double turnDeg() { return vt; }

    /** True while stepping; false when standing. */
    public boolean walking() { return walking; }

    /** True while the left foot swings (or would swing next in double support). */
    public boolean leftSwings() { return leftSwings; }

    public FootTarget leftFoot() { return foot(left, true); }
    public FootTarget rightFoot() { return foot(right, false); }

    /** Torso's lateral shift this cycle, metres to the left (the feet are drawn the other way). */
    public double sway() { return sway; }

    // --- the model ----------------------------------------------------------------------------

    /** The request clamped to the limits, jointly: inside the ellipsoid of the three maxima. */
    double[] limit(WalkVelocity r) { return limit(r, new double[3]); }

    private double[] limit(WalkVelocity r, double[] out) {
        double f = clamp(r.forward(), -c.maxBackward(), c.maxForward());
        double l = clamp(r.left(), -c.maxLeft(), c.maxLeft());
        double th = clamp(r.turnDeg(), -c.maxTurnDeg(), c.maxTurnDeg());
        double fMax = f >= 0 ? c.maxForward() : c.maxBackward();
        double n = sq(ratio(f, fMax)) + sq(ratio(l, c.maxLeft())) + sq(ratio(th, c.maxTurnDeg()));
        if (n > 1) {
            double k = 1 / Math.sqrt(n);
            f *= k; l *= k; th *= k;
        }
        out[0] = f;
        out[1] = l;
        out[2] = th;
        return out;
    }

    /** The turn rate allowed at a forward speed: maxTurnDeg standing, turnAtFullSpeedDeg at maxForward, linear between. */
    double turnAllowed(double forward) {
        if (forward <= 0 || c.maxForward() == 0) return c.maxTurnDeg();
        double share = Math.min(1, forward / c.maxForward());
        return c.maxTurnDeg() - (c.maxTurnDeg() - Math.min(c.turnAtFullSpeedDeg(), c.maxTurnDeg())) * share;
    }

    /** The forward speed at which a turn rate is allowed (the inverse of {@link #turnAllowed}). */
    double forwardAllowed(double turnDeg) {
        double full = Math.min(c.turnAtFullSpeedDeg(), c.maxTurnDeg()), a = Math.abs(turnDeg);
        if (a <= full) return c.maxForward();
        return c.maxForward() * Math.max(0, c.maxTurnDeg() - a) / (c.maxTurnDeg() - full);
    }

    private void neutral(boolean isLeft, double[] pose) {
        pose[0] = c.footForward();
        pose[1] = (isLeft ? 1 : -1) * (g.hipHalfWidth() + c.stanceWidth());
        pose[2] = 0;
    }

    private boolean atNeutral() {
        double[] n = neutralPose;
        neutral(true, n);
        boolean ok = near(left, n);
        neutral(false, n);
        return ok && near(right, n);
    }

    private static boolean near(double[] a, double[] b) {
        return Math.abs(a[0] - b[0]) < 1e-3 && Math.abs(a[1] - b[1]) < 1e-3 && Math.abs(a[2] - b[2]) < 0.5;
    }

    /** A foot on the ground seen from a body that moved (df, dl) and turned dTheta (deg). */
    private static void carry(double[] p, double df, double dl, double dThetaDeg) {
        double a = Math.toRadians(-dThetaDeg), co = Math.cos(a), si = Math.sin(a);
        double f = p[0] - df, l = p[1] - dl;
        p[0] = co * f - si * l;
        p[1] = si * f + co * l;
        p[2] -= dThetaDeg;
    }

    /** Where the swinging foot lands: neutral moved by the body's motion over the coming stance (see the class comment). */
    private void landing(boolean isLeft, double[] out) {
        double stance = c.stepSeconds() * (1 + c.doubleSupport());
        double sign = isLeft ? 1 : -1;
        double mf = vf * stance, ml = vl * stance, mt = vt * stance;
        double yaw = mt / 2 + sign * Math.abs(mt) / 2;
        yaw = isLeft ? clamp(yaw, 0, c.maxFootYawDeg()) : clamp(yaw, -c.maxFootYawDeg(), 0);
        double[] n = neutralPose;
        neutral(isLeft, n);
        double a = Math.toRadians(yaw), co = Math.cos(a), si = Math.sin(a);
        out[0] = mf / 2 + co * n[0] - si * n[1] + placeForward;
        out[1] = ml / 2 + sign * Math.abs(ml) / 2 + si * n[0] + co * n[1] + placeLeft;
        out[2] = yaw;
    }

    /**
     * Keeps a foot turned outward and on its own side of the centre line, with its heel corner (which
     * turns inward when the foot yaws outward) included: then the two feet can never touch or cross.
     */
    void keepApart(double[] p, boolean isLeft) {
        // outward yaw only (the hip yaw-pitch joint's range): a stance foot that the body's turn would
        // twist inward (only when a turn starts with that foot down) slides instead
        p[2] = isLeft ? clamp(p[2], 0, c.maxFootYawDeg()) : clamp(p[2], -c.maxFootYawDeg(), 0);
        double yaw = Math.toRadians(Math.abs(p[2]));
        double inner = HEEL * Math.sin(yaw) + FOOT_HALF_WIDTH * Math.cos(yaw) + CENTRE_MARGIN;
        if (isLeft) p[1] = Math.max(p[1], inner);
        else p[1] = Math.min(p[1], -inner);
    }

    private FootTarget foot(double[] p, boolean isLeft) {
        return new FootTarget(p[0], p[1] - sway, lift(isLeft), p[2]);
    }

    private double lift(boolean isLeft) {
        boolean swinging = walking && isLeft == leftSwings;
        return swinging ? lift : 0;
    }

    private void computeTargets() {
        Arrays.fill(targets, 0);
        leg(left, true);
        leg(right, false);
        // arms hang slightly forward and out; each swings with the opposite leg
        double n = c.footForward();
        targets[Joint.LAJ1.ordinal()] = -80 + c.armSwingDeg() * (right[0] - n);
        targets[Joint.RAJ1.ordinal()] = -80 + c.armSwingDeg() * (left[0] - n);
        targets[Joint.LAJ2.ordinal()] = 8;
        targets[Joint.RAJ2.ordinal()] = -8;
        targets[Joint.LAJ4.ordinal()] = -30;
        targets[Joint.RAJ4.ordinal()] = 30;
        for (Joint j : JOINTS) targets[j.ordinal()] = JointLimits.clamp(j, targets[j.ordinal()]);
    }

    /** The leg's six targets for a foot's ground pose p, as {@link #foot} would give its FootTarget. */
    private void leg(double[] p, boolean isLeft) {
        double legHeight = c.legExtension() * (g.thigh() + g.shank());
        // ankle relative to the torso centre, horizontal frame (x right, y forward, z up)
        double x = -(p[1] - sway), y = p[0], z = -(g.hipBelowTorso() + legHeight) + lift(isLeft);
        // into the torso frame, pitched forward by the lean: Rx(lean)
        double lean = Math.toRadians(c.torsoLeanDeg()), co = Math.cos(lean), si = Math.sin(lean);
        double ty = co * y - si * z, tz = si * y + co * z;
        double hipX = (isLeft ? -1 : 1) * g.hipHalfWidth();
        int base = (isLeft ? Joint.LLJ1 : Joint.RLJ1).ordinal();   // lj1..lj6 in FootPoseIk.Angles' order
        ik.solveInto(g, isLeft, x - hipX, ty, tz + g.hipBelowTorso(), p[2], c.torsoLeanDeg(), targets, base);
    }

    private static double ratio(double v, double max) { return max == 0 ? 0 : v / max; }
    private static double sq(double v) { return v * v; }
    private static double clamp(double v, double lo, double hi) { return Math.max(lo, Math.min(hi, v)); }
    private static double clampAbs(double v, double m) { return clamp(v, -m, m); }
}

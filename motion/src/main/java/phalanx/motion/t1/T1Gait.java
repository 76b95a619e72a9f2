package phalanx.motion.t1;

import java.util.ArrayList;
import java.util.List;

/**
 * An open-loop IK walk for the Booster T1 on rcssservermj, with optional torso-attitude feedback at the ankles
 * and hips. Each step (half a cycle) the torso sways sideways over the support foot (a sine), the swing foot
 * lifts (a sine over the single-support part) and moves to half a step ahead while the support foot moves
 * back linearly at the commanded speed; turning alternates the hip yaws the same way. Feet are placed by
 * {@link T1LegKinematics} with the soles level in the torso frame.
 *
 * <p>{@link #next} at zero velocity steps on the spot; {@link #stand()} holds a still pose (and resets the
 * gait, so the next {@code next} starts a fresh step with the left foot as support).
 *
 * <p>Built on a {@link T1GaitConfig.Blend}, every cycle's config lies between the blend's walk and turn presets by
 * the command's turn share (moving at most the blend's rate per second); {@link #stand()} is then the stand
 * config's pose, and the first step of a walk moves the feet from its stance to the walking config's.
 */
public final class T1Gait {
    private static final String[] LEFT = {"lle1", "lle2", "lle3", "lle4", "lle5", "lle6"};
    private static final String[] RIGHT = {"rle1", "rle2", "rle3", "rle4", "rle5", "rle6"};

    /** Largest feedback correction of a joint, rad. */
    static final double MAX_CORRECTION = 0.2;

    /** This cycle's config: the one preset, or the blend at {@link #share}. */
    private T1GaitConfig c;
    private final T1GaitConfig.Blend blend;
    /** The stand pose's config (the one preset, or the blend's stand); its stance is where a walk starts from. */
    private final T1GaitConfig standConfig;
    /** The turn share of the blend (0 walk preset .. 1 turn preset), and the share {@link #c} was made for. */
    private double share, madeFor;
    private final double maxVx, maxVy, maxTurn;
    private final T1LegKinematics leftLeg, rightLeg;
    private final double[] qLeft = new double[6], qRight = new double[6];
    private final double[] prevLeft = new double[6], prevRight = new double[6];
    private boolean havePrev;

    // gait state: time in the step, which foot supports, each foot's offset (x, y, yaw) now and at step start
    private double t;
    private boolean leftSupport = true;
    private int steps;
    private final double[] foot = new double[6];      // left x, y, yaw, right x, y, yaw
    private final double[] footStart = new double[6];
    private double vx, vy, turn;                       // ramped commands
    private double roll, pitch, rollRate, pitchRate;  // feedback, radians
    private double lastSway, lastLiftLeft, lastLiftRight;

    public T1Gait(T1GaitConfig config) {
        this(config, null, config);
    }

    /** Blending the walk and turn presets by the command; {@code stand} gives the still pose (and the kick's start). */
    public T1Gait(T1GaitConfig.Blend blend, T1GaitConfig stand) {
        this(blend.walk(), blend, stand);
    }

    private T1Gait(T1GaitConfig config, T1GaitConfig.Blend blend, T1GaitConfig stand) {
        this.c = config;
        this.blend = blend;
        this.standConfig = stand;
        // the commands are limited by the widest preset: the share, not the limit, decides how it walks
        this.maxVx = blend == null ? config.maxVx() : Math.max(blend.walk().maxVx(), blend.turn().maxVx());
        this.maxVy = blend == null ? config.maxVy() : Math.max(blend.walk().maxVy(), blend.turn().maxVy());
        this.maxTurn = blend == null ? config.maxTurn() : Math.max(blend.walk().maxTurn(), blend.turn().maxTurn());
        this.leftLeg = new T1LegKinematics(config, true);
        this.rightLeg = new T1LegKinematics(config, false);
        double[] init = {-0.3, 0, 0, 0.6, -0.3, 0};
        System.arraycopy(init, 0, qLeft, 0, 6);
        System.arraycopy(init, 0, qRight, 0, 6);
    }

    public T1GaitConfig config() { return c; }

    /** The blend's turn share now (0: the walk preset, 1: the turn preset; 0 without a blend). */
    public double turnShare() { return blend == null ? 0 : share; }

    /** Torso attitude for the feedback: roll and pitch (rad, from torso_quat), their rates (rad/s, torso_gyro). */
    public void feedback(double rollRad, double pitchRad, double rollRateRadS, double pitchRateRadS) {
        this.roll = rollRad;
        this.pitch = pitchRad;
        this.rollRate = rollRateRadS;
        this.pitchRate = pitchRateRadS;
    }

    /** A still standing pose, both feet at the stance position, and a reset gait. */
    public List<JointCommand> stand() {
        t = 0;
        steps = 0;
        leftSupport = true;
        vx = vy = turn = 0;
        java.util.Arrays.fill(foot, 0);
        java.util.Arrays.fill(footStart, 0);
        lastSway = lastLiftLeft = lastLiftRight = 0;
        if (blend != null) {
            c = standConfig;
            share = 0;
            madeFor = -1;
        }
        return pose(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, false);
    }

    /** One 0.02 s cycle of walking at the given command (clamped to the config's limits). */
    public List<JointCommand> next(double vxMps, double vyMps, double turnDegPerS) {
        double ax = c.accel() * c.dt();
        double turnTarget = clamp(turnDegPerS, -maxTurn, maxTurn), turnStep = Math.toRadians(200 * c.accel() * c.dt());
        if (blend == null) {
            vx = approach(vx, clamp(vxMps, -maxVx / 2, maxVx), ax);
            vy = approach(vy, clamp(vyMps, -maxVy, maxVy), ax);
        } else {
            // the speed grows only while the turn now is within what the new speed allows; the turn is held within
            // what the speed allows (T1GaitConfig.Blend): walking and turning fast do not mix
            double tx = clamp(vxMps, -maxVx / 2, maxVx), ty = clamp(vyMps, -maxVy, maxVy), dx = blend.decel() * c.dt();
            // slowing down at the blend's decel (slower than accel: stopping from 0.6 m/s at 0.5 m/s/s fell)
            double nx = approach(vx, tx, Math.abs(tx) < Math.abs(vx) ? dx : ax), ny = approach(vy, ty, Math.abs(ty) < Math.abs(vy) ? dx : ax);
            boolean faster = Math.hypot(nx, ny) > Math.hypot(vx, vy);
            if (!faster || Math.abs(Math.toDegrees(turn)) <= blend.allowedTurn(Math.hypot(nx, ny)) + 1e-9) {
                vx = nx;
                vy = ny;
            }
            double lim = blend.allowedTurn(Math.hypot(vx, vy));
            turnTarget = clamp(turnTarget, -lim, lim);
        }
        turn = approach(turn, Math.toRadians(turnTarget), turnStep);
        if (blend != null) reblend();
        t += c.dt();
        if (t >= c.stepTime() - 1e-9) {
            t -= c.stepTime();
            leftSupport = !leftSupport;
            steps++;
            System.arraycopy(foot, 0, footStart, 0, 6);
        }
        double s = t / c.stepTime();
        double ts = c.stepTime();
        int sup = leftSupport ? 0 : 3, sw = leftSupport ? 3 : 0;
        // support foot: linearly back at the commanded velocity
        double[] supEnd = {-vx * c.strideScale() * ts / 2, -vy * ts / 2, -turn * ts / 2};
        // capture-step-like feedback: step further towards where the torso leans
        double lean = pitch - Math.toRadians(c.torsoPitchDeg());
        double[] swEnd = {vx * c.strideScale() * ts / 2 + clamp(c.stepPitchGain() * lean, -0.08, 0.08),
                vy * ts / 2 - clamp(c.stepRollGain() * roll, -0.05, 0.05), turn * ts / 2};
        double d = c.doubleSupport();
        double u = clamp((s - d / 2) / (1 - d), 0, 1);
        double smooth = 0.5 - 0.5 * Math.cos(Math.PI * u);
        // the support foot moves back with the linear inverted pendulum's shape (sinh; the ankle then needs little
        // torque: its 20 N m cannot hold the CoM far from it), blended with a straight line
        double tc = Math.sqrt(c.comHeight() / 9.81), half = ts / (2 * tc);
        double lip = 0.5 + 0.5 * Math.sinh((s - 0.5) * ts / tc) / Math.sinh(half);
        double along = (1 - c.lipmBlend()) * s + c.lipmBlend() * lip;
        for (int k = 0; k < 3; k++) {
            foot[sup + k] = footStart[sup + k] + (supEnd[k] - footStart[sup + k]) * (k == 2 ? s : along);
            foot[sw + k] = footStart[sw + k] + (swEnd[k] - footStart[sw + k]) * smooth;
        }
        double ramp = Math.min(1.0, (steps + s) / 1.0);
        if (blend != null) {
            // the first step moves the stance from the stand config's to the walking one's, as sway and lift grow
            T1GaitConfig st = standConfig;
            stanceX = st.footX() + (c.footX() - st.footX()) * ramp;
            stanceY = st.footY() + (c.footY() - st.footY()) * ramp;
            stanceZ = st.footZ() + (c.footZ() - st.footZ()) * ramp;
        }
        // lateral sway over the support foot: the pendulum's cosh shape, 0 at the step's ends, c.sway() mid-step
        double shape = (1 - Math.cosh((s - 0.5) * ts / tc) / Math.cosh(half)) / (1 - 1 / Math.cosh(half));
        double sway = ramp * c.sway() * shape * (leftSupport ? 1 : -1);
        double lift = ramp * c.lift() * Math.sin(Math.PI * u);
        double liftL = leftSupport ? 0 : lift, liftR = leftSupport ? lift : 0;
        return pose(foot[0], foot[1], foot[2], foot[3], foot[4], foot[5], sway, liftL, liftR, ramp, true);
    }

    private double stanceX = Double.NaN, stanceY, stanceZ;

    /** Moves the turn share towards the ramped command's (at most the blend's rate) and makes this cycle's config. */
    private void reblend() {
        double a = Math.abs(Math.toDegrees(turn)) / blend.turn().maxTurn();
        double b = Math.hypot(vx / blend.walk().maxVx(), vy / blend.walk().maxVy());
        if (a + b >= blend.stepOnSpot()) share = approach(share, a / (a + b), blend.ratePerS() * c.dt());
        if (share != madeFor) {
            c = blend.walk().lerp(blend.turn(), share);
            madeFor = share;
        }
    }

    /** Whether the left foot is the support foot in the current step. */
    public boolean leftSupport() { return leftSupport; }

    /** Current foot offsets from stance (left x, y, yaw, right x, y, yaw; m, rad). */
    public double[] footOffsets() { return foot.clone(); }

    /** Current lift of the left and right foot (m). */
    public double[] lifts() { return new double[]{lastLiftLeft, lastLiftRight}; }

    private List<JointCommand> pose(double lx, double ly, double lyaw, double rx, double ry, double ryaw,
                                    double sway, double liftL, double liftR, double ramp, boolean walking) {
        lastSway = sway;
        lastLiftLeft = liftL;
        lastLiftRight = liftR;
        // keep the feet from crossing: the inner side offset is limited
        ly = Math.max(ly, -0.02);
        ry = Math.min(ry, 0.02);
        lyaw = Math.max(lyaw, -0.35);
        ryaw = Math.min(ryaw, 0.35);
        // a foot turned by yaw relative to the torso sits rotated about the torso's vertical axis too, so that
        // turning pivots about the torso, not about the support ankle
        double fx = c.footX(), fy = c.footY(), fz = c.footZ();
        if (blend != null && walking) {
            fx = stanceX;
            fy = stanceY;
            fz = stanceZ;
        }
        double[] pl = rotate(fx + lx, fy + ly, lyaw), pr = rotate(fx + rx, -fy + ry, ryaw);
        leftLeg.inverse(pl[0], pl[1] - sway, fz + liftL, lyaw, qLeft);
        rightLeg.inverse(pr[0], pr[1] - sway, fz + liftR, ryaw, qRight);
        double[] l = qLeft.clone(), r = qRight.clone();
        // feedback: torso pitched forward (pitch > 0, about +y) -> ankle pitch up by pitchGain x error: the foot turns
        // toes-down against the shank, which pushes the body back; roll likewise at the ankle roll
        double pe = pitch - Math.toRadians(c.torsoPitchDeg());
        double pc = clamp(c.pitchGain() * pe + c.pitchRateGain() * pitchRate, -MAX_CORRECTION, MAX_CORRECTION);
        double rc = clamp(c.rollGain() * roll + c.rollRateGain() * rollRate, -MAX_CORRECTION, MAX_CORRECTION);
        l[4] += pc;
        r[4] += pc;
        l[5] -= rc;
        r[5] -= rc;
        // hip strategy: torso pitched forward (pitch > 0) -> hips extend to bring it back; rolled -> hip roll
        double hp = clamp(c.hipPitchGain() * pe, -MAX_CORRECTION, MAX_CORRECTION);
        double hr = clamp(c.hipRollGain() * roll, -MAX_CORRECTION, MAX_CORRECTION);
        l[0] += hp;
        r[0] += hp;
        l[1] += hr;
        r[1] += hr;
        List<JointCommand> out = new ArrayList<>(23);
        double[][] rl = leftLeg.ranges(), rr = rightLeg.ranges();
        for (int k = 0; k < 6; k++) {
            l[k] = clamp(l[k], rl[k][0], rl[k][1]);
            r[k] = clamp(r[k], rr[k][0], rr[k][1]);
        }
        for (int k = 0; k < 6; k++) {
            boolean ankle = k >= 4;
            double kp = ankle ? c.ankleKp() : c.legKp(), kd = ankle ? c.ankleKd() : c.legKd();
            double dl = havePrev && walking ? (l[k] - prevLeft[k]) / c.dt() : 0;
            double dr = havePrev && walking ? (r[k] - prevRight[k]) / c.dt() : 0;
            out.add(new JointCommand(LEFT[k], Math.toDegrees(l[k]), Math.toDegrees(dl), kp, kd, 0));
            out.add(new JointCommand(RIGHT[k], Math.toDegrees(r[k]), Math.toDegrees(dr), kp, kd, 0));
        }
        System.arraycopy(l, 0, prevLeft, 0, 6);
        System.arraycopy(r, 0, prevRight, 0, 6);
        havePrev = true;
        out.add(new JointCommand("lae1", 0, 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("rae1", 0, 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("lae2", c.shoulderRollDeg(), 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("rae2", -c.shoulderRollDeg(), 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("lae3", c.elbowDeg(), 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("rae3", c.elbowDeg(), 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("lae4", 0, 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("rae4", 0, 0, c.armKp(), c.armKd(), 0));
        out.add(new JointCommand("he1", 0, 0, c.armKp() / 4, c.armKd() / 4, 0));
        out.add(new JointCommand("he2", 0, 0, c.armKp() / 4, c.armKd() / 4, 0));
        out.add(new JointCommand("te1", 0, 0, c.legKp(), c.legKd(), 0));
        return out;
    }

    private static double[] rotate(double x, double y, double yaw) {
        double cs = Math.cos(yaw), sn = Math.sin(yaw);
        return new double[]{cs * x - sn * y, sn * x + cs * y};
    }

    private static double approach(double v, double target, double step) {
        return v < target ? Math.min(target, v + step) : Math.max(target, v - step);
    }

    static double clamp(double v, double lo, double hi) { return Math.max(lo, Math.min(hi, v)); }
}

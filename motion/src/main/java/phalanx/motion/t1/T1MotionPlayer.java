package phalanx.motion.t1;

import phalanx.model.robot.T1Joints;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * Plays a {@link T1Motion} as rcssservermj PD commands, like FC Portugal's Slot_Engine: from the measured joint
 * angles at the start to the first pose by its time, then pose to pose by linear interpolation, each target sent
 * with the interpolation's velocity (so the PD's damping does not brake the motion). A joint the file does not
 * name holds its angle at the start.
 */
public final class T1MotionPlayer {
    /**
     * Stiffness (N m / rad) and damping (N m s / rad) per joint group; the server clips the torque at the joint's
     * limit (t1-joints.tsv), so a stiff joint is a strong one only up to that.
     */
    public record Gains(double legKp, double legKd, double armKp, double armKd, double headKp, double headKd) {
        /** The gait's leg gains (T1GaitConfig: 200, 5) everywhere but the head, which only needs to follow. */
        public static final Gains DEFAULT = new Gains(200, 5, 100, 3, 20, 1);

        double kp(String actuator) { return actuator.startsWith("he") ? headKp : actuator.matches("[lr]ae\\d") ? armKp : legKp; }
        double kd(String actuator) { return actuator.startsWith("he") ? headKd : actuator.matches("[lr]ae\\d") ? armKd : legKd; }
    }

    private static final List<String> ACTUATORS = T1Joints.actuators();

    private final double dt;
    private final double[] kp = new double[ACTUATORS.size()], kd = new double[ACTUATORS.size()];
    private T1Motion motion;
    private final double[] start = new double[ACTUATORS.size()], prev = new double[ACTUATORS.size()];
    private int[] column;   // per actuator: its column in the motion, or -1
    private double t;
    private boolean active;

    public T1MotionPlayer(double dtSeconds, Gains gains) {
        this.dt = dtSeconds;
        for (int i = 0; i < ACTUATORS.size(); i++) {   // once here, not per joint per cycle
            kp[i] = gains.kp(ACTUATORS.get(i));
            kd[i] = gains.kd(ACTUATORS.get(i));
        }
    }

    /** Starts a motion from the measured joint angles (degrees, by actuator name). */
    public void start(T1Motion m, ToDoubleFunction<String> measuredDeg) {
        motion = m;
        column = new int[ACTUATORS.size()];
        for (int i = 0; i < ACTUATORS.size(); i++) {
            column[i] = m.actuators().indexOf(ACTUATORS.get(i));
            start[i] = measuredDeg.applyAsDouble(ACTUATORS.get(i));
            prev[i] = start[i];
        }
        t = 0;
        active = true;
    }

    public boolean active() { return active; }

    public void stop() { active = false; }

    /** Seconds of the motion still to play after the last {@link #next()} (0 when done). */
    public double remainingS() { return active ? Math.max(0, motion.seconds() - t) : 0; }

    /** The motion being played (null before the first start). */
    public T1Motion motion() { return motion; }

    /** The pose being moved to, or "done". */
    public String poseName() {
        if (!active) return "done";
        int[] times = motion.timesMs();
        for (int p = 0; p < times.length; p++) if (t * 1000 < times[p]) return motion.poseNames().get(p);
        return motion.poseNames().get(times.length - 1);
    }

    /** One control cycle; after the last pose's time the last pose, and {@link #active()} turns false. */
    public List<JointCommand> next() {
        t += dt;
        int[] times = motion.timesMs();
        double ms = t * 1000;
        if (ms >= times[times.length - 1] - 1e-6) active = false;
        List<JointCommand> out = new ArrayList<>(ACTUATORS.size());
        for (int i = 0; i < ACTUATORS.size(); i++) {
            String a = ACTUATORS.get(i);
            double q = column[i] < 0 ? start[i] : target(i, column[i], ms);
            double dq = active ? (q - prev[i]) / dt : 0;
            prev[i] = q;
            out.add(new JointCommand(a, q, dq, kp[i], kd[i], 0));
        }
        return out;
    }

    /** Actuator i's target (column k of the motion) at ms: linear between the poses around it, from its start angle before the first. */
    private double target(int i, int k, double ms) {
        int[] times = motion.timesMs();
        double[][] poses = motion.posesDeg();
        if (ms >= times[times.length - 1]) return poses[times.length - 1][k];
        int p = 0;
        while (ms >= times[p]) p++;
        double t0 = p == 0 ? 0 : times[p - 1], a = p == 0 ? start[i] : poses[p - 1][k];
        double s = times[p] == t0 ? 1 : (ms - t0) / (times[p] - t0);
        return a + (poses[p][k] - a) * s;
    }
}

package phalanx.motion.t1;

import phalanx.model.robot.T1Joints;
import phalanx.model.robot.T1Model;
import phalanx.motion.MotionFileException;

import java.nio.file.Path;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * Getting the T1 up after a fall on rcssservermj: once the torso is tilted past {@link Config#fallenTiltDeg()},
 * wait until it lies still (or {@link Config#maxWaitS()}), play get_up_front or get_up_back (motions/t1,
 * {@link T1MotionPlayer}) for the side it lies on, then {@link Config#recoverS()} of a recovery stand (the gait's
 * stand pose with the recovery config's torso feedback, {@link T1GaitConfig#getUpRecovery()}: the get-ups are leaps,
 * and most that failed fell forward in the first second after landing), and if it is down at the end of either,
 * start again. The referee takes a field player off after 15 s on the ground (docs/rcssservermj.md), so a get-up
 * must not wait long.
 */
public final class T1GetUp {
    /**
     * @param fallenTiltDeg     torso up axis this far from vertical = fallen (the agent's upright test: 60 deg)
     * @param stillDegS         lying still: gyro below this, deg/s, on both tilt axes
     * @param maxWaitS          longest wait for lying still before the get-up starts anyway, s
     * @param recoverS          the recovery stand after the motion, s (0: none, the caller's gait at once)
     * @param riseFrontS        the rise of get_up_front: its last seconds, in which the motion's ankle and hip pitch get
     *                          the torso's pitch rate as feedback (0: none)
     * @param riseBackS         the same for get_up_back
     * @param riseAnkleRateGain in the rise, ankle pitch added per rad/s of forward torso pitch rate (toes down), rad
     * @param riseHipRateGain   in the rise, hip pitch added per rad/s of forward torso pitch rate (positive: hips open), rad
     */
    public record Config(double fallenTiltDeg, double stillDegS, double maxWaitS, double recoverS,
                         double riseFrontS, double riseBackS, double riseAnkleRateGain, double riseHipRateGain) {
        public static final Config DEFAULT = new Config(60, 30, 1.0, RECOVER_S, RISE_FRONT_S, RISE_BACK_S, RISE_ANKLE_RATE_GAIN, RISE_HIP_RATE_GAIN);

        public Config {
            if (!(fallenTiltDeg > 0 && fallenTiltDeg < 180)) throw new IllegalArgumentException("fallenTiltDeg must be in (0, 180), got " + fallenTiltDeg);
            if (!(stillDegS > 0)) throw new IllegalArgumentException("stillDegS must be positive, got " + stillDegS);
            if (!(maxWaitS >= 0)) throw new IllegalArgumentException("maxWaitS must be at least 0, got " + maxWaitS);
            if (!(recoverS >= 0)) throw new IllegalArgumentException("recoverS must be at least 0, got " + recoverS);
            if (!(riseFrontS >= 0)) throw new IllegalArgumentException("riseFrontS must be at least 0, got " + riseFrontS);
            if (!(riseBackS >= 0)) throw new IllegalArgumentException("riseBackS must be at least 0, got " + riseBackS);
            if (!Double.isFinite(riseAnkleRateGain)) throw new IllegalArgumentException("riseAnkleRateGain must be finite, got " + riseAnkleRateGain);
            if (!Double.isFinite(riseHipRateGain)) throw new IllegalArgumentException("riseHipRateGain must be finite, got " + riseHipRateGain);
        }

        public Config withRecoverS(double s) { return with("recoverS", s); }

        /** A copy with a named field changed (the bench's --getup-set name=value). */
        public Config with(String name, double v) { return phalanx.motion.RecordFields.withDouble(this, name, v); }
    }

    /** See {@link Config#recoverS()}; measured in motion/README.md "T1 get-up". */
    static final double RECOVER_S = 1.0;
    /** See {@link Config#riseFrontS()} and the others: off until measured. */
    static final double RISE_FRONT_S = 0, RISE_BACK_S = 0, RISE_ANKLE_RATE_GAIN = 0, RISE_HIP_RATE_GAIN = 0;

    public enum State { UP, LYING, GETTING_UP, RECOVERING }

    private final T1Motion front, back;
    private final Config c;
    private final T1MotionPlayer player;
    private final T1Gait recovery;
    private State state = State.UP;
    private double lyingSince, recoverUntil;
    private long getUps, retries;
    private boolean failed;   // the last get-up ended with the robot still down

    /** With {@code recovery} as the recovery stand's config (its dt is the cycle). */
    public T1GetUp(T1Motion front, T1Motion back, Config config, T1GaitConfig recovery) {
        this.front = front;
        this.back = back;
        this.c = config;
        this.player = new T1MotionPlayer(recovery.dt(), T1MotionPlayer.Gains.DEFAULT);
        this.recovery = new T1Gait(recovery);
    }

    /** get_up_front.motion and get_up_back.motion from a folder (motions/t1), the default config and recovery stand. */
    public static T1GetUp load(Path dir) throws MotionFileException {
        return load(dir, Config.DEFAULT, T1GaitConfig.getUpRecovery());
    }

    public static T1GetUp load(Path dir, Config config, T1GaitConfig recovery) throws MotionFileException {
        return new T1GetUp(T1MotionLoader.load(dir.resolve("get_up_front.motion")), T1MotionLoader.load(dir.resolve("get_up_back.motion")),
                config, recovery);
    }

    public State state() { return state; }

    /**
     * Forgets the state (up, nothing playing); the counts stay. For a caller whose clock starts again (the bench's
     * trials), as the waits compare times.
     */
    public void reset() {
        state = State.UP;
        player.stop();
        failed = false;
    }

    /** Get-ups started so far. */
    public long getUps() { return getUps; }

    /** Of those, the ones started because the one before ended with the robot still down. */
    public long retries() { return retries; }

    /** The motion playing ("recover" in the recovery stand), or null. */
    public String playing() { return state == State.GETTING_UP ? player.motion().name() : state == State.RECOVERING ? "recover" : null; }

    /**
     * One cycle: the torso quaternion (w, x, y, z), the gyro (deg/s), the measured joint angles (deg, by actuator)
     * and the time (s). Returns the get-up's joint commands while it is in control, or null when the robot is up
     * (then the caller's gait acts; while lying still before a get-up, too). The recovery stand after the motion is
     * part of the get-up: its commands are returned too.
     */
    public List<JointCommand> update(double[] quat, double[] gyroDegS, ToDoubleFunction<String> measuredDeg, double time) {
        if (state == State.RECOVERING) {
            if (fallen(quat)) {
                lieDown(time);
            } else if (time >= recoverUntil - 1e-9) {
                state = State.UP;
                return null;
            } else {
                double[] rp = T1Model.rollPitch(quat);
                recovery.feedback(rp[0], rp[1], gyroDegS == null ? 0 : Math.toRadians(gyroDegS[0]), gyroDegS == null ? 0 : Math.toRadians(gyroDegS[1]));
                return recovery.stand();
            }
        }
        if (state == State.GETTING_UP) {
            List<JointCommand> out = player.next();
            double rise = player.motion() == front ? c.riseFrontS() : c.riseBackS();
            if (player.remainingS() < rise - 1e-9 && gyroDegS != null) out = withRiseFeedback(out, Math.toRadians(gyroDegS[1]));
            if (!player.active()) {
                if (fallen(quat)) {
                    lieDown(time);
                } else if (c.recoverS() > 0) {
                    state = State.RECOVERING;
                    recoverUntil = time + c.recoverS();
                } else {
                    state = State.UP;
                }
            }
            return out;
        }
        if (!fallen(quat)) {
            state = State.UP;
            failed = false;
            return null;
        }
        if (state == State.UP) {
            state = State.LYING;
            lyingSince = time;
        }
        boolean still = gyroDegS == null || (Math.abs(gyroDegS[0]) < c.stillDegS() && Math.abs(gyroDegS[1]) < c.stillDegS());
        if (!still && time - lyingSince < c.maxWaitS()) return null;
        state = State.GETTING_UP;
        getUps++;
        if (failed) retries++;
        failed = false;
        player.start(faceDown(quat) ? front : back, measuredDeg);
        return player.next();
    }

    /**
     * The rise's feedback: the torso pitching forward (a positive pitch rate) turns the ankles toes-down and opens the
     * hips (as T1Gait's feedback does), each correction within T1Gait.MAX_CORRECTION and the joint's range.
     */
    List<JointCommand> withRiseFeedback(List<JointCommand> cmds, double pitchRateRadS) {
        double ankle = Math.toDegrees(clamp(c.riseAnkleRateGain() * pitchRateRadS)), hip = Math.toDegrees(clamp(c.riseHipRateGain() * pitchRateRadS));
        List<JointCommand> out = new java.util.ArrayList<>(cmds.size());
        for (JointCommand j : cmds) {
            String a = j.actuator();
            double add = a.equals("lle5") || a.equals("rle5") ? ankle : a.equals("lle1") || a.equals("rle1") ? hip : 0;
            out.add(add == 0 ? j : new JointCommand(a, T1Joints.byActuator(a).clampDeg(j.qDeg() + add), j.dqDeg(), j.kp(), j.kd(), j.tau()));
        }
        return out;
    }

    private static double clamp(double rad) {
        return Math.max(-T1Gait.MAX_CORRECTION, Math.min(T1Gait.MAX_CORRECTION, rad));
    }

    /** Still down after a get-up or in its recovery stand: a failed try, lying since {@code time}. */
    private void lieDown(double time) {
        state = State.LYING;
        lyingSince = time;
        failed = true;
    }

    boolean fallen(double[] q) {
        return T1Model.uprightness(q) < Math.cos(Math.toRadians(c.fallenTiltDeg()));
    }

    /** Whether the torso's forward (x) axis points down more than up: lying on the front. */
    static boolean faceDown(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        return 2 * (x * z - w * y) < 0;
    }
}

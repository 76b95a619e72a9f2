package phalanx.motion.walk;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.motion.MotionConfig;
import phalanx.motion.control.JointVelocities;
import phalanx.motion.kinematics.LegGeometry;

/**
 * Runs the {@link WalkGenerator} against the robot: each cycle the gait's joint targets (plus the
 * gyro corrections) become hinge velocities the way the keyframe controller makes them:
 * v = gain · (target − predicted) / cycle, where "predicted" is the reading plus the command already
 * on its way (the server applies a reply one cycle after the reading it answers), clamped to the
 * joint's speed cap. Values in, values out.
 */
public final class WalkController {
    private final WalkConfig config;
    private final WalkGenerator generator;
    private final double dt;
    private final int latency;
    private final double[] caps = new double[Joint.COUNT];
    private final double[] lastCommand = new double[Joint.COUNT];

    public WalkController(WalkConfig config, int robotType, MotionConfig motion) {
        this.config = config;
        this.dt = motion.cycleSeconds();
        this.latency = motion.latencyCycles();
        this.generator = new WalkGenerator(config, LegGeometry.forType(robotType), dt);
        for (Joint j : Joint.values()) caps[j.ordinal()] = speedCap(robotType, j, motion.maxJointSpeed());
    }

    /**
     * The hinge speed cap of a joint in rad/s: the motion config's cap, except type 2's faster ankle
     * pitch (8.80667) and slower ankle roll (3.47234) (naorobottypes.rb). Commanding more than the
     * server grants would spoil the prediction of where the joint is.
     */
    static double speedCap(int type, Joint j, double defaultCap) {
        if (type == 2 && (j == Joint.LLJ5 || j == Joint.RLJ5)) return Math.max(defaultCap, 8.80667);
        if (type == 2 && (j == Joint.LLJ6 || j == Joint.RLJ6)) return Math.min(defaultCap, 3.47234);
        return defaultCap;
    }

    /**
     * One cycle: the joint readings (degrees) and gyro (deg/s, torso frame; null when absent) of the
     * message being answered, and the requested velocity. Returns the hinge velocities to send.
     */
    public JointVelocities step(JointAngles current, Vector3 gyro, WalkVelocity request) {
        double[] target = generator.step(request);
        if (gyro != null && gyro.isFinite()) {
            double pitch = config.gyroPitchGain() * gyro.x(), roll = config.gyroRollGain() * gyro.y();
            target[Joint.LLJ5.ordinal()] += pitch;
            target[Joint.RLJ5.ordinal()] += pitch;
            target[Joint.LLJ2.ordinal()] += roll;
            target[Joint.RLJ2.ordinal()] += roll;
        }
        double[] out = new double[Joint.COUNT];
        for (Joint j : Joint.values()) {
            int i = j.ordinal();
            if (!current.has(j)) {
                out[i] = Double.NaN;
                lastCommand[i] = 0;
                continue;
            }
            double predicted = current.degrees(j) + latency * Math.toDegrees(lastCommand[i]) * dt;
            double v = config.servoGain() * Math.toRadians(target[i] - predicted) / dt;
            v = Math.max(-caps[i], Math.min(caps[i], v));
            out[i] = v;
            lastCommand[i] = v;
        }
        return JointVelocities.of(out);
    }

    /** This cycle's motion as commanded, for {@code BeliefStore.odometry(forward, left, turnDeg)}. */
    public Odometry odometry() { return generator.odometry(); }

    /** The walk's velocity now (after limits). */
    public WalkVelocity velocity() { return generator.velocity(); }

    /** True while stepping. */
    public boolean walking() { return generator.walking(); }

    /** The gait itself (foot targets, sway), e.g. for drawing. */
    public WalkGenerator generator() { return generator; }
}

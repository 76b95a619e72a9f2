package phalanx.motion.walk;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.motion.MotionConfig;
import phalanx.motion.control.JointVelocities;
import phalanx.model.robot.NaoModel;

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
    // reused every cycle: the gait's targets plus this cycle's corrections, and the commands
    private final double[] target = new double[Joint.COUNT], out = new double[Joint.COUNT];
    private static final Joint[] JOINTS = Joint.values();
    /** Share of the accelerometer's tilt taken each cycle (time constant about 1 s at 50 Hz). */
    private static final double TILT_PULL = 0.02;
    private double pitchForward, rollRight;   // deg, estimated torso tilt
    private double headingError;    // deg: integrated (gyro yaw rate - commanded turn rate) while walking
    private final double[] from = new double[Joint.COUNT];   // deg: where a keyframe motion left the joints
    private int blendCycles, blended;   // the targets move from `from` to the gait's over blendCycles cycles

    public WalkController(WalkConfig config, int robotType, MotionConfig motion) {
        this.config = config;
        this.dt = motion.cycleSeconds();
        this.latency = motion.latencyCycles();
        this.generator = new WalkGenerator(config, NaoModel.ofType(robotType), dt);
        for (Joint j : Joint.values()) caps[j.ordinal()] = speedCap(robotType, j, motion.maxJointSpeed());
    }

    /**
     * Start from the pose a keyframe motion left (degrees; joints without a reading are not blended):
     * for the next {@code cycles} cycles the targets go from that pose to the gait's on a cosine ramp,
     * instead of the joints snapping there at full speed. The kicks and get-ups end in a deeper crouch
     * than the walk stands in (hip 38°, knee −67° against 32°, −56° for type 0); the snap straightened the
     * legs and pitched the torso back within a few cycles, while a kick still had it leaning back
     * (docs/matches.md, session 20). The caller keeps the request at zero meanwhile.
     */
    public void startFrom(JointAngles pose, int cycles) {
        for (Joint j : JOINTS) from[j.ordinal()] = pose != null && pose.has(j) ? pose.degrees(j) : Double.NaN;
        blendCycles = Math.max(0, cycles);
        blended = 0;
    }

    /**
     * The hinge speed cap of a joint in rad/s: the motion config's cap, except type 2's slower ankle
     * roll (3.47234, naorobottypes.rb): commanding more than the server grants would spoil the
     * prediction of where the joint is. Type 2's faster ankle pitch (8.80667) is not used: with it
     * the walk fell within 30 s at 0.65 m/s; capped like the other types it walks 0.79 m/s
     * (motion/README.md).
     */
    static double speedCap(int type, Joint j, double defaultCap) {
        if (type == 2 && (j == Joint.LLJ6 || j == Joint.RLJ6)) return Math.min(defaultCap, 3.47234);
        return defaultCap;
    }

    /**
     * One cycle: the joint readings (degrees), gyro (deg/s) and accelerometer (m/s², both torso frame)
     * of the message being answered, and the requested velocity; any of them may be null (absent
     * from the message): no readings give no commands, no request means stop. Returns the hinge
     * velocities to send.
     */
    public JointVelocities step(JointAngles current, Vector3 gyro, Vector3 acc, WalkVelocity request) {
        if (current == null) current = JointAngles.none();   // a message without joint readings: no commands
        if (request == null) request = WalkVelocity.ZERO;
        boolean haveGyro = gyro != null && gyro.isFinite();
        tilt(gyro, acc);
        double pitchErr = pitchForward - config.torsoLeanDeg();
        if (generator.walking() && haveGyro) {
            headingError += (gyro.z() - generator.turnDeg()) * dt;
            headingError = Math.max(-45, Math.min(45, headingError));
        } else {
            headingError = 0;
        }
        double hold = request.isZero() ? 0 : -config.gyroYawGain() * headingError; // a zero request must let the walk stop
        WalkVelocity wanted = hold == 0 ? request : new WalkVelocity(request.forward(), request.left(), request.turnDeg() + hold);
        double[] gait = generator.advance(wanted,
                clampAbs(config.tiltPlaceForward() * pitchErr, 0.04), clampAbs(-config.tiltPlaceLeft() * rollRight, 0.03));
        System.arraycopy(gait, 0, target, 0, Joint.COUNT);   // the generator's own array: the corrections go on a copy
        double hip = config.tiltHipPitch() * pitchErr;
        target[Joint.LLJ3.ordinal()] += hip;
        target[Joint.RLJ3.ordinal()] += hip;
        if (haveGyro) {
            double pitch = config.gyroPitchGain() * gyro.x(), roll = config.gyroRollGain() * gyro.y();
            target[Joint.LLJ5.ordinal()] += pitch;
            target[Joint.RLJ5.ordinal()] += pitch;
            target[Joint.LLJ2.ordinal()] += roll;
            target[Joint.RLJ2.ordinal()] += roll;
        }
        if (blended < blendCycles) {
            double share = 0.5 - 0.5 * Math.cos(Math.PI * ++blended / blendCycles);
            for (int i = 0; i < Joint.COUNT; i++) if (!Double.isNaN(from[i])) target[i] = from[i] + share * (target[i] - from[i]);
        }
        for (Joint j : JOINTS) {
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
        return JointVelocities.of(out);   // a copy
    }

    /**
     * Torso tilt, complementary filter: the gyro's rates integrated, pulled slowly toward the tilt the
     * accelerometer shows (gravity's direction; accelerations of the walk average out). Gyro x is
     * the pitch rate (nose up positive), y the roll rate (right side down positive), deg/s; the
     * accelerometer reads (0, 0, 9.81) upright.
     */
    private void tilt(Vector3 gyro, Vector3 acc) {
        if (gyro != null && gyro.isFinite()) {
            pitchForward -= gyro.x() * dt;
            rollRight += gyro.y() * dt;
        }
        if (acc != null && acc.isFinite() && acc.z() > 1) {
            double p = Math.toDegrees(Math.atan2(-acc.y(), acc.z())), r = Math.toDegrees(Math.atan2(-acc.x(), acc.z()));
            pitchForward += TILT_PULL * (p - pitchForward);
            rollRight += TILT_PULL * (r - rollRight);
        }
    }

    /** Torso pitch, degrees forward, as estimated. */
    public double pitchForward() { return pitchForward; }

    /** Torso roll, degrees to the right, as estimated. */
    public double rollRight() { return rollRight; }

    private static double clampAbs(double v, double m) { return Math.max(-m, Math.min(m, v)); }

    /** This cycle's motion as commanded, for {@code BeliefStore.odometry(forward, left, turnDeg)}. */
    public Odometry odometry() { return generator.odometry(); }

    /** The walk's velocity now (after limits). */
    public WalkVelocity velocity() { return generator.velocity(); }

    /** True while stepping. */
    public boolean walking() { return generator.walking(); }

    /** The gait itself (foot targets, sway), e.g. for drawing. */
    public WalkGenerator generator() { return generator; }
}

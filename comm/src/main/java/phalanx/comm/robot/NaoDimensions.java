package phalanx.comm.robot;

/**
 * The simulated Nao's lengths per heterogeneous robot type 0-4, in metres: the one table that both
 * localization (camera height, leg odometry) and motion (leg kinematics) read, because neither may
 * depend on the other. Source: rcssserver3d 0.7.3 {@code rsg/agent/nao/naoleg.rsg}, {@code naoneckhead.rsg}
 * and the type table of {@code naorobottypes.rb} (hip-knee = -ThighRelHip2_Z + 0.08,
 * knee-ankle = 0.045 - AnkleRelShank_Z); checked against the standing torso heights in the
 * recordings README (0.3839 m for types 0/2/4, 0.4205 for type 1, 0.4396 for type 3).
 *
 * @param type         robot type 0-4 (type 0 is plain nao.rsg)
 * @param thigh        hip pitch axis to knee axis
 * @param shank        knee axis to ankle axis
 * @param hipHalfWidth torso centre to a hip joint, sideways
 */
public record NaoDimensions(int type, double thigh, double shank, double hipHalfWidth) {

    /** Torso centre to the neck yaw joint. */
    public static final double NECK_ABOVE_TORSO = 0.09;
    /** Neck to the head centre, where the camera is. */
    public static final double HEAD_ABOVE_NECK = 0.065;
    /** The head pitch hinge sits this far below the head centre. */
    public static final double PITCH_AXIS_BELOW_HEAD = 0.005;
    /** Torso centre down to the hip pitch axis. */
    public static final double HIP_BELOW_TORSO = 0.115;
    /** Ankle axis down to the sole (foot centre 0.04 below, half the 0.02 m foot box). */
    public static final double SOLE_BELOW_ANKLE = 0.05;

    private static final NaoDimensions[] TYPES = {
            new NaoDimensions(0, 0.12, 0.10, 0.055),
            new NaoDimensions(1, 0.05832 + 0.08, 0.045 + 0.07332, 0.055),
            new NaoDimensions(2, 0.12, 0.10, 0.055),
            new NaoDimensions(3, 0.067868424 + 0.08, 0.045 + 0.082868424, 0.072954143),
            new NaoDimensions(4, 0.12, 0.10, 0.055),
    };

    /** The dimensions of robot type 0-4. */
    public static NaoDimensions ofType(int type) {
        if (type < 0 || type >= TYPES.length) throw new IllegalArgumentException("robot type must be 0-4, got " + type);
        return TYPES[type];
    }

    /** Torso centre above the soles with straight legs and an upright torso. */
    public double standingTorsoHeight() {
        return HIP_BELOW_TORSO + thigh + shank + SOLE_BELOW_ANKLE;
    }

    /** Torso centre to the camera (head centre) with the head level. */
    public static double cameraAboveTorso() {
        return NECK_ABOVE_TORSO + HEAD_ABOVE_NECK;
    }
}

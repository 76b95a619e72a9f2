package phalanx.model.robot;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

/**
 * The simulated Nao's lengths per heterogeneous robot type 0-4, in metres: the one description of the
 * body that localization (camera height, leg odometry), motion (leg kinematics) and the agent read.
 * The per-type lengths are data (resources phalanx/model/robots/nao-types.tsv, README there: rcssserver3d 0.7.3
 * {@code naoleg.rsg} and {@code naorobottypes.rb}); checked against the standing torso heights in the recordings
 * README (0.3839 m for types 0/2/4, 0.4205 for type 1, 0.4396 for type 3). The fixed offsets below come from
 * {@code naoneckhead.rsg} and {@code naoleg.rsg}. Joint ranges: {@link JointLimits}; the camera
 * height from the legs: {@link CameraHeight}.
 *
 * @param type         robot type 0-4 (type 0 is plain nao.rsg)
 * @param thigh        hip pitch axis to knee axis
 * @param shank        knee axis to ankle axis
 * @param hipHalfWidth torso centre to a hip joint, sideways
 */
public record NaoModel(int type, double thigh, double shank, double hipHalfWidth) {

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
    /** Torso centre to the camera (head centre) with the head level (M1 monitor: 0.5379 - 0.3829). */
    private static final double CAMERA_ABOVE_TORSO = NECK_ABOVE_TORSO + HEAD_ABOVE_NECK;

    /** Types 0-4 in order, from robots/nao-types.tsv. */
    private static final NaoModel[] TYPES = load();

    private static NaoModel[] load() {
        RobotTable t = RobotTable.load("nao-types.tsv", 4);
        NaoModel[] types = new NaoModel[t.size()];
        for (int i = 0; i < t.size(); i++) {
            int type = (int) t.number(i, 0);
            if (type != i) throw new IllegalStateException("robot table nao-types.tsv: type " + type + " in row " + i);
            types[i] = new NaoModel(type, t.number(i, 1), t.number(i, 2), t.number(i, 3));
        }
        return types;
    }

    /** Robot type 0, plain nao.rsg. */
    public static final NaoModel TYPE_0 = TYPES[0];

    /** The body of robot type 0-4. */
    public static NaoModel ofType(int type) {
        if (type < 0 || type >= TYPES.length) throw new IllegalArgumentException("robot type must be 0-4, got " + type);
        return TYPES[type];
    }

    /** Torso centre to the hip pitch axis (vertical). */
    public double hipBelowTorso() { return HIP_BELOW_TORSO; }

    /** Ankle axis to the sole. */
    public double ankleAboveSole() { return SOLE_BELOW_ANKLE; }

    /** Torso centre to the camera with the head level. */
    public double cameraAboveTorso() { return CAMERA_ABOVE_TORSO; }

    /** Torso centre above the soles with straight legs and an upright torso. */
    public double standingTorsoHeight() {
        return HIP_BELOW_TORSO + thigh + shank + SOLE_BELOW_ANKLE;
    }

    /**
     * The sole of one leg relative to the torso centre along the torso's up axis and forward axis,
     * from the sagittal joints only (thesis 4.6 Walk to Ball: ankle, knee and hip pitch), as
     * {forward, up}. Missing joint readings count as 0.
     */
    public double[] soleInTorso(JointAngles joints, boolean left) {
        double h = rad(joints, left ? Joint.LLJ3 : Joint.RLJ3);
        double k = rad(joints, left ? Joint.LLJ4 : Joint.RLJ4);
        double a = rad(joints, left ? Joint.LLJ5 : Joint.RLJ5);
        // Positive hip pitch swings the leg forward (hinge axis = torso right, ODE sign convention).
        double fwd = thigh * Math.sin(h) + shank * Math.sin(h + k) + SOLE_BELOW_ANKLE * Math.sin(h + k + a);
        double up = -HIP_BELOW_TORSO - thigh * Math.cos(h) - shank * Math.cos(h + k) - SOLE_BELOW_ANKLE * Math.cos(h + k + a);
        return new double[] {fwd, up};
    }

    private static double rad(JointAngles j, Joint joint) {
        if (j == null || !j.has(joint)) return 0;
        double r = j.radians(joint);
        return Double.isFinite(r) ? r : 0;
    }
}

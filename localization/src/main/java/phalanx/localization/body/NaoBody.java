package phalanx.localization.body;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

import phalanx.comm.robot.NaoDimensions;

/**
 * The simulated Nao's body as localization uses it: the lengths of {@link NaoDimensions} (the one
 * table per robot type) and the leg's forward kinematics for leg odometry and the camera height.
 *
 * @param thigh hip pitch axis to knee axis
 * @param shank knee axis to ankle axis
 */
public record NaoBody(int type, double thigh, double shank) {

    public static final double NECK_ABOVE_TORSO = NaoDimensions.NECK_ABOVE_TORSO;
    public static final double HEAD_ABOVE_NECK = NaoDimensions.HEAD_ABOVE_NECK;
    public static final double PITCH_AXIS_BELOW_HEAD = NaoDimensions.PITCH_AXIS_BELOW_HEAD;
    public static final double HIP_BELOW_TORSO = NaoDimensions.HIP_BELOW_TORSO;
    public static final double SOLE_BELOW_ANKLE = NaoDimensions.SOLE_BELOW_ANKLE;

    private static final NaoBody[] TYPES = new NaoBody[5];
    static {
        for (int t = 0; t < TYPES.length; t++) {
            NaoDimensions d = NaoDimensions.ofType(t);
            TYPES[t] = new NaoBody(t, d.thigh(), d.shank());
        }
    }

    /** The body of a heterogeneous robot type 0-4 (type 0 is plain nao.rsg). */
    public static NaoBody ofType(int type) {
        NaoDimensions.ofType(type); // refuses an unknown type with its number
        return TYPES[type];
    }

    /** Torso centre above the soles with straight legs and an upright torso. */
    public double standingTorsoHeight() {
        return NaoDimensions.ofType(type).standingTorsoHeight();
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

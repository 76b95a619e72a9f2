package phalanx.localization.body;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

/**
 * The simulated Nao's dimensions that localization needs, per robot type (heterogeneous types 0-4).
 * Source: SimSpark rcssserver3d {@code rsg/agent/nao/naoneckhead.rsg} (neck 0.09 m above the torso
 * centre, head 0.065 m above the neck, the head pitch hinge 0.005 m below the head centre, the
 * RestrictedVisionPerceptor on the head node itself) and {@code naoleg.rsg} with the type table of
 * {@code naosoccersim.rb} (hip 0.115 m below the torso; hip-knee = -ThighRelHip2_Z + 0.08,
 * knee-ankle = 0.045 - AnkleRelShank_Z; ankle 0.04 above the foot centre, the sole 0.01 below it),
 * as published in github.com/UNSWComputing/SimSpark. Lengths in metres.
 *
 * @param thigh hip pitch axis to knee axis
 * @param shank knee axis to ankle axis
 */
public record NaoBody(int type, double thigh, double shank) {

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

    private static final NaoBody[] TYPES = {
            new NaoBody(0, 0.12, 0.10),
            new NaoBody(1, 0.05832 + 0.08, 0.045 + 0.07332),
            new NaoBody(2, 0.12, 0.10),
            new NaoBody(3, 0.067868424 + 0.08, 0.045 + 0.082868424),
            new NaoBody(4, 0.12, 0.10),
    };

    /** The body of a heterogeneous robot type 0-4 (type 0 is plain nao.rsg). */
    public static NaoBody ofType(int type) {
        if (type < 0 || type >= TYPES.length) throw new IllegalArgumentException("robot type must be 0-4, got " + type);
        return TYPES[type];
    }

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

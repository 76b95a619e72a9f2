package phalanx.motion.kinematics;

import phalanx.comm.robot.NaoDimensions;

/**
 * Lengths of the simulated Nao that the kinematics need, in metres, per robot type, taken from
 * {@link NaoDimensions} (the one table, shared with localization).
 *
 * @param hipBelowTorso   torso centre to the hip pitch axis (vertical)
 * @param hipHalfWidth    torso centre to a hip (lateral)
 * @param thigh           hip pitch axis to knee axis
 * @param shank           knee axis to ankle axis
 * @param ankleAboveSole  ankle axis to the sole
 * @param cameraAboveTorso torso centre to the camera (neck 0.09 + head 0.065; M1 monitor: 0.5379 - 0.3829)
 */
public record LegGeometry(double hipBelowTorso, double hipHalfWidth, double thigh, double shank,
                          double ankleAboveSole, double cameraAboveTorso) {

    public static final LegGeometry TYPE_0 = of(NaoDimensions.ofType(0));

    /** Geometry of robot type 0-4 (-1 = nao.rsg, the same as type 0). */
    public static LegGeometry forType(int type) {
        if (type < -1 || type > 4) throw new IllegalArgumentException("robot type must be 0-4 (or -1 for nao.rsg), got " + type);
        if (type == -1 || type == 0) return TYPE_0;
        return of(NaoDimensions.ofType(type));
    }

    private static LegGeometry of(NaoDimensions d) {
        return new LegGeometry(NaoDimensions.HIP_BELOW_TORSO, d.hipHalfWidth(), d.thigh(), d.shank(),
                NaoDimensions.SOLE_BELOW_ANKLE, NaoDimensions.cameraAboveTorso());
    }

    /** Torso centre height when standing straight, all joints 0. */
    public double standingTorsoHeight() { return ankleAboveSole + shank + thigh + hipBelowTorso; }
}

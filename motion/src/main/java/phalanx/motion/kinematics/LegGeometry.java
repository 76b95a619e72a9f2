package phalanx.motion.kinematics;

/**
 * Lengths of the simulated Nao that the kinematics need, in metres, per robot type (the server's
 * naoleg.rsg with the per-type values of nao_hetero; checked against the standing torso heights in
 * the recordings README: 0.3839 for types 0/2/4, 0.4205 for type 1, 0.4396 for type 3).
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

    public static final LegGeometry TYPE_0 = new LegGeometry(0.115, 0.055, 0.12, 0.10, 0.05, 0.155);

    /** Geometry of robot type 0-4 (-1 = nao.rsg, the same as type 0). */
    public static LegGeometry forType(int type) {
        return switch (type) {
            case -1, 0, 2, 4 -> TYPE_0;
            case 1 -> new LegGeometry(0.115, 0.055, 0.13832, 0.11832, 0.05, 0.155);
            case 3 -> new LegGeometry(0.115, 0.072954143, 0.147868424, 0.127868424, 0.05, 0.155);
            default -> throw new IllegalArgumentException("robot type must be 0-4 (or -1 for nao.rsg), got " + type);
        };
    }

    /** Torso centre height when standing straight, all joints 0. */
    public double standingTorsoHeight() { return ankleAboveSole + shank + thigh + hipBelowTorso; }
}

package phalanx.motion.kinematics;

import phalanx.model.field.Angles;
import phalanx.model.robot.NaoModel;
/**
 * Inverse and forward kinematics of one whole leg of the simulated Nao, hip yaw-pitch included, so
 * a foot can be put at a position AND turned (the walk's turning steps).
 *
 * <p>The model (naoleg.rsg, rcssserver3d 0.7.3): torso frame x right, y forward, z up. All three hip
 * axes meet at the hip point, both ankle axes at the ankle point (the 5 mm offsets of the model are
 * ignored). Going down the chain:
 * <ol>
 *   <li>lj1, hip yaw-pitch, about the axis (-1, 0, -1)/√2 for the left leg and (-1, 0, 1)/√2 for the
 *       right one: 45° between the vertical and the lateral axis, range [-90°, 1°]. A negative angle
 *       turns that foot's toes outward (left foot counter-clockwise, right foot clockwise) and tilts
 *       it a little; the IK compensates the tilt with the other joints. On the real Nao the two
 *       yaw-pitch joints are one motor; in the simulator they are two independent hinges, and this
 *       model drives them independently. Since each can only turn its foot outward, a walk turns
 *       with the leading foot yawed out and the trailing foot following (see the walk's README).</li>
 *   <li>lj2, hip roll, about y (positive moves the leg to the robot's left);</li>
 *   <li>lj3, hip pitch, about x (positive swings the thigh forward); thigh {@link NaoModel#thigh()};</li>
 *   <li>lj4, knee, about x (bends negative); shank {@link NaoModel#shank()};</li>
 *   <li>lj5, ankle pitch, about x (positive lifts the toes); lj6, ankle roll, about y.</li>
 * </ol>
 * Rotations are right-handed about the axes above (the simulator's hinge convention, which the
 * keyframe files and {@link LegIk} already rely on).
 */
public final class FootPoseIk {
    private static final double S = Math.sqrt(0.5);

    /** Scratch 3x3 matrices of {@link #solveInto}, so the walk's IK allocates nothing. */
    private final double[] rf = new double[9], r1 = new double[9], r2 = new double[9], m1 = new double[9], m2 = new double[9];

    /** An IK with its own scratch space (one per user: not thread-safe); see {@link #solveInto}. */
    public FootPoseIk() {}

    /** The six leg angles in degrees: yaw-pitch (lj1), hip roll, hip pitch, knee, ankle pitch, ankle roll. */
    public record Angles(double yawPitch, double hipRoll, double hipPitch, double knee, double anklePitch, double ankleRoll) {}

    /**
     * The angles that put the ankle at ({@code x} right, {@code y} forward, {@code z} up) metres from
     * the hip joint, with the foot rotated by Rx(pitch)·Rz(yaw) relative to the torso: the foot is
     * turned by {@code yawDeg} (counter-clockwise positive) in a plane that is tilted by
     * {@code pitchDeg} (toes up positive) — a flat foot under a torso leaning forward by λ has
     * pitch λ. Targets out of reach are pulled in along the hip-ankle line.
     */
    public static Angles solve(NaoModel g, boolean left, double x, double y, double z, double yawDeg, double pitchDeg) {
        double[] q = new double[6];
        new FootPoseIk().solveInto(g, left, x, y, z, yawDeg, pitchDeg, q, 0);
        return new Angles(q[0], q[1], q[2], q[3], q[4], q[5]);
    }

    /**
     * {@link #solve} without allocating: the six angles in degrees, in the order of {@link Angles},
     * go to {@code out[at]} to {@code out[at + 5]}.
     */
    public void solveInto(NaoModel g, boolean left, double x, double y, double z, double yawDeg, double pitchDeg,
                          double[] out, int at) {
        mul(rotX(Math.toRadians(pitchDeg), r1), rotZ(Math.toRadians(yawDeg), r2), rf);
        // the hip seen from the foot: v = Rf^T (-p)
        double vx = -(rf[0] * x + rf[3] * y + rf[6] * z);
        double vy = -(rf[1] * x + rf[4] * y + rf[7] * z);
        double vz = -(rf[2] * x + rf[5] * y + rf[8] * z);
        double a = g.thigh(), b = g.shank();
        double len = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double reach = Math.max(Math.abs(a - b) + 1e-6, Math.min(a + b - 1e-9, len));
        if (len > 1e-12 && reach != len) {
            double k = reach / len;
            vx *= k; vy *= k; vz *= k;
        }
        double knee = -Math.acos(clamp((reach * reach - a * a - b * b) / (2 * a * b)));
        double ankleRoll = Math.atan2(-vx, vz);
        double wy = vy;
        double wz = -Math.sin(ankleRoll) * vx + Math.cos(ankleRoll) * vz;
        double anklePitch = Math.atan2(wy, wz) - Math.atan2(a * Math.sin(knee), a * Math.cos(knee) + b);
        // R_hip·Rx(hipPitch) = Rf·Ry(-ankleRoll)·Rx(-(knee+anklePitch)); turn the yaw-pitch axis onto z
        mul(mul(rf, rotY(-ankleRoll, r1), m1), rotX(-(knee + anklePitch), r2), m2);
        double[] n = mul(rotY(Math.toRadians(left ? -45 : 45), r1), m2, m1);
        // n = Rz(t1)·Ry(t2)·Rx(t3)
        double t2 = -Math.asin(clamp(n[6]));
        double t1 = Math.atan2(n[3], n[0]);
        double t3 = Math.atan2(n[7], n[8]);
        double yawPitch = left ? -t1 : t1;
        double hipRoll = left ? t2 + Math.PI / 4 : t2 - Math.PI / 4;
        out[at] = Math.toDegrees(yawPitch);
        out[at + 1] = Math.toDegrees(hipRoll);
        out[at + 2] = Math.toDegrees(t3);
        out[at + 3] = Math.toDegrees(knee);
        out[at + 4] = Math.toDegrees(anklePitch);
        out[at + 5] = Math.toDegrees(ankleRoll);
    }

    /**
     * Forward kinematics of the same chain: {x, y, z} of the ankle relative to the hip (metres)
     * followed by the foot's rotation relative to the torso (row-major 3x3): 12 numbers.
     */
    public static double[] forward(NaoModel g, boolean left, Angles q) {
        double[] axis = left ? new double[] {-S, 0, -S} : new double[] {-S, 0, S};
        double[] hip = mul(rot(axis, Math.toRadians(q.yawPitch())), rotY(Math.toRadians(q.hipRoll())));
        double[] thigh = mul(hip, rotX(Math.toRadians(q.hipPitch())));
        double[] shank = mul(thigh, rotX(Math.toRadians(q.knee())));
        double[] foot = mul(mul(shank, rotX(Math.toRadians(q.anklePitch()))), rotY(Math.toRadians(q.ankleRoll())));
        double[] out = new double[12];
        for (int r = 0; r < 3; r++) out[r] = -g.thigh() * thigh[r * 3 + 2] - g.shank() * shank[r * 3 + 2];
        System.arraycopy(foot, 0, out, 3, 9);
        return out;
    }

    /** Rx(pitch)·Rz(yaw), row-major, as {@link #solve} reads its foot rotation. */
    public static double[] footRotation(double yawDeg, double pitchDeg) {
        return mul(rotX(Math.toRadians(pitchDeg)), rotZ(Math.toRadians(yawDeg)));
    }

    // --- 3x3 row-major helpers ------------------------------------------------------------------

    static double[] rotX(double t) { return rotX(t, new double[9]); }
    static double[] rotY(double t) { return rotY(t, new double[9]); }
    static double[] rotZ(double t) { return rotZ(t, new double[9]); }

    private static double[] rotX(double t, double[] r) {
        double c = Math.cos(t), s = Math.sin(t);
        r[0] = 1; r[1] = 0; r[2] = 0;
        r[3] = 0; r[4] = c; r[5] = -s;
        r[6] = 0; r[7] = s; r[8] = c;
        return r;
    }

    private static double[] rotY(double t, double[] r) {
        double c = Math.cos(t), s = Math.sin(t);
        r[0] = c; r[1] = 0; r[2] = s;
        r[3] = 0; r[4] = 1; r[5] = 0;
        r[6] = -s; r[7] = 0; r[8] = c;
        return r;
    }

    private static double[] rotZ(double t, double[] r) {
        double c = Math.cos(t), s = Math.sin(t);
        r[0] = c; r[1] = -s; r[2] = 0;
        r[3] = s; r[4] = c; r[5] = 0;
        r[6] = 0; r[7] = 0; r[8] = 1;
        return r;
    }

    /** Rotation by {@code t} radians about the unit axis {@code u} (Rodrigues). */
    static double[] rot(double[] u, double t) {
        double c = Math.cos(t), s = Math.sin(t), k = 1 - c, x = u[0], y = u[1], z = u[2];
        return new double[] {
            c + x * x * k, x * y * k - z * s, x * z * k + y * s,
            y * x * k + z * s, c + y * y * k, y * z * k - x * s,
            z * x * k - y * s, z * y * k + x * s, c + z * z * k};
    }

    static double[] mul(double[] p, double[] q) { return mul(p, q, new double[9]); }

    /** p·q into r (which must be neither p nor q). */
    private static double[] mul(double[] p, double[] q, double[] r) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) r[i * 3 + j] = p[i * 3] * q[j] + p[i * 3 + 1] * q[3 + j] + p[i * 3 + 2] * q[6 + j];
        return r;
    }

    private static double clamp(double c) { return Math.max(-1, Math.min(1, c)); }
}

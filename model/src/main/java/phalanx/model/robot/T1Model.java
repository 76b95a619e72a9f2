package phalanx.model.robot;

/**
 * The Booster T1 as rcssservermj 0.2.1 models it (rcsssmj resources/robots/T1/robot.xml): the chain from the
 * torso site, whose world pose the server sends as ground truth ({@code torso_pos}, {@code torso_quat}), to the
 * camera site its vision is measured from (sim/simulation.py: polar coordinates in the camera site's frame).
 */
public final class T1Model {
    private static final RobotTable CHAIN = RobotTable.load("t1-camera.tsv", 4);
    /** robot.xml body H1 (head yaw, axis z) in the torso (robots/t1-camera.tsv). */
    static final double[] YAW_IN_TORSO = link("head_yaw_in_torso");
    /** Body H2 (head pitch, axis y: positive looks down) in H1. */
    static final double[] PITCH_IN_YAW = link("head_pitch_in_yaw");
    /** Site "camera" in H2. */
    static final double[] CAMERA_IN_PITCH = link("camera_in_pitch");
    /** The torso body's height in the model as built, standing straight. */
    public static final double TORSO_HEIGHT = 0.6735;

    private T1Model() {}

    private static double[] link(String name) {
        for (int i = 0; i < CHAIN.size(); i++) {
            if (CHAIN.text(i, 0).equals(name)) return new double[] {CHAIN.number(i, 1), CHAIN.number(i, 2), CHAIN.number(i, 3)};
        }
        throw new IllegalStateException("robot table t1-camera.tsv has no " + name);
    }

    /**
     * Where a point seen at polar (distance m, azimuth °, elevation °) is in the world, from the torso's world
     * pose (quaternion w x y z, position) and the head's yaw and pitch in degrees (perceptors q_hj1, q_hj2).
     */
    public static double[] seenToWorld(double[] quat, double[] torso, double headYawDeg, double headPitchDeg,
                                       double distance, double azimuthDeg, double elevationDeg) {
        double[][] r = rotation(quat);
        double[][] ry = mul(r, rotZ(Math.toRadians(headYawDeg)));
        double[][] rc = mul(ry, rotY(Math.toRadians(headPitchDeg)));
        double az = Math.toRadians(azimuthDeg), el = Math.toRadians(elevationDeg);
        double[] local = {distance * Math.cos(el) * Math.cos(az), distance * Math.cos(el) * Math.sin(az), distance * Math.sin(el)};
        double[] p = torso.clone();
        add(p, apply(r, YAW_IN_TORSO));
        add(p, apply(ry, PITCH_IN_YAW));
        add(p, apply(rc, CAMERA_IN_PITCH));
        add(p, apply(rc, local));
        return p;
    }

    /** The torso's heading in the world, degrees: the yaw of its x axis on the ground. */
    public static double headingDeg(double[] quat) {
        double[][] r = rotation(quat);
        return Math.toDegrees(Math.atan2(r[1][0], r[0][0]));
    }

    /** The torso's roll and pitch in radians (Z-Y-X Euler angles; pitch positive leaning forward). */
    public static double[] rollPitch(double[] quat) {
        double[][] r = rotation(quat);
        return new double[] {Math.atan2(r[2][1], r[2][2]), Math.asin(Math.max(-1, Math.min(1, -r[2][0])))};
    }

    /** The quaternion with the same roll and pitch and no yaw (R = Ry(pitch) Rx(roll)): what an IMU alone knows. */
    public static double[] withoutYaw(double[] quat) {
        double[] rp = rollPitch(quat);
        double cr = Math.cos(rp[0] / 2), sr = Math.sin(rp[0] / 2), cp = Math.cos(rp[1] / 2), sp = Math.sin(rp[1] / 2);
        return new double[] {cp * cr, cp * sr, sp * cr, -sp * sr};
    }

    /** The z component of the torso's up axis: 1 upright, 0 lying. */
    public static double uprightness(double[] quat) {
        return rotation(quat)[2][2];
    }

    static double[][] rotation(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        w /= n; x /= n; y /= n; z /= n;
        return new double[][] {
                {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    }

    private static double[][] rotZ(double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return new double[][] {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
    }

    private static double[][] rotY(double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return new double[][] {{c, 0, s}, {0, 1, 0}, {-s, 0, c}};
    }

    private static double[][] mul(double[][] a, double[][] b) {
        double[][] m = new double[3][3];
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) for (int k = 0; k < 3; k++) m[i][j] += a[i][k] * b[k][j];
        return m;
    }

    private static double[] apply(double[][] m, double[] v) {
        return new double[] {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2], m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
    }

    private static void add(double[] p, double[] v) {
        for (int i = 0; i < 3; i++) p[i] += v[i];
    }
}

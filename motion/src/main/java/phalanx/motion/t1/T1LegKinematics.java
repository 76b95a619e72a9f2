package phalanx.motion.t1;

/**
 * Forward and inverse kinematics of one T1 leg in the torso frame (x forward, y left, z up; origin the torso
 * body's origin). Joint order as the actuators lle1..6 / rle1..6: hip pitch (y), hip roll (x), hip yaw (z),
 * knee pitch (y), ankle pitch (y), ankle roll (x). The end frame is the foot link's frame (the ankle roll
 * joint); body offsets are those of rcsssmj resources/robots/T1/robot.xml, held in {@link T1GaitConfig}.
 * The IK is a damped least-squares iteration on the analytic Jacobian, warm-started from the last solution.
 */
public final class T1LegKinematics {
    private final T1GaitConfig c;
    private final double side; // +1 left, -1 right

    public T1LegKinematics(T1GaitConfig config, boolean left) {
        this.c = config;
        this.side = left ? 1 : -1;
    }

    public boolean left() { return side > 0; }

    /** Joint ranges in radians, [joint][min, max], for this side (robot.xml). */
    public double[][] ranges() {
        double[][] r = new double[6][];
        r[0] = new double[]{-1.8, 1.57};
        r[1] = side > 0 ? new double[]{-0.2, 1.57} : new double[]{-1.57, 0.2};
        r[2] = new double[]{-1.0, 1.0};
        r[3] = new double[]{0.0, 2.34};
        r[4] = new double[]{-0.87, 0.35};
        r[5] = new double[]{-0.44, 0.44};
        return r;
    }

    /**
     * Forward kinematics: the foot frame's pose as a row-major 3x4 matrix [R | p] (12 values), and, if
     * {@code axes} / {@code origins} are not null, each joint's world axis and origin (6 x 3) for the Jacobian.
     */
    public double[] forward(double[] q, double[][] axes, double[][] origins) {
        double[] t = identity();
        t = mul(t, trans(c.waistX(), 0, c.waistZ()));
        t = mul(t, trans(0, side * c.hipY(), 0));
        t = joint(t, 0, 1, q[0], axes, origins);
        t = mul(t, trans(0, 0, -c.hipPitchToRoll()));
        t = joint(t, 1, 0, q[1], axes, origins);
        t = mul(t, trans(0, 0, -c.hipRollToYaw()));
        t = joint(t, 2, 2, q[2], axes, origins);
        t = mul(t, trans(c.yawToKneeX(), 0, -c.yawToKneeZ()));
        t = joint(t, 3, 1, q[3], axes, origins);
        t = mul(t, trans(0, 0, -c.shank()));
        t = joint(t, 4, 1, q[4], axes, origins);
        t = mul(t, trans(0, side * c.anklePitchToRollY(), -c.anklePitchToRoll()));
        t = joint(t, 5, 0, q[5], axes, origins);
        return t;
    }

    /** Foot frame position (x, y, z) for joint angles q (radians). */
    public double[] footPosition(double[] q) {
        double[] t = forward(q, null, null);
        return new double[]{t[3], t[7], t[11]};
    }

    /**
     * Solves for a foot frame at {@code (x, y, z)} with the sole level in the torso frame and turned by
     * {@code yaw} about z, starting from {@code q} (radians, overwritten with the solution, clamped to the
     * joint ranges). Returns the remaining position error in metres.
     */
    public double inverse(double x, double y, double z, double yaw, double[] q) {
        double err = solve(x, y, z, yaw, q);
        if (err > 1e-4) { // stuck at a joint limit from a far warm start: once more from the crouch
            double[] seed = {-0.3, 0, 0, 0.6, -0.3, 0};
            double again = solve(x, y, z, yaw, seed);
            if (again < err) {
                System.arraycopy(seed, 0, q, 0, 6);
                err = again;
            }
        }
        return err;
    }

    private double solve(double x, double y, double z, double yaw, double[] q) {
        double cy = Math.cos(yaw), sy = Math.sin(yaw);
        double[] rt = {cy, -sy, 0, sy, cy, 0, 0, 0, 1};
        double[][] axes = new double[6][3], origins = new double[6][3];
        double[][] range = ranges();
        double err = Double.MAX_VALUE;
        for (int it = 0; it < 30; it++) {
            double[] t = forward(q, axes, origins);
            double[] e = new double[6];
            e[0] = x - t[3];
            e[1] = y - t[7];
            e[2] = z - t[11];
            err = Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            // orientation error: the rotation vector of Rt * R^T, small-angle (vee of the skew part)
            double[] r = {t[0], t[1], t[2], t[4], t[5], t[6], t[8], t[9], t[10]};
            double[] m = new double[9];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    m[i * 3 + j] = rt[i * 3] * r[j * 3] + rt[i * 3 + 1] * r[j * 3 + 1] + rt[i * 3 + 2] * r[j * 3 + 2];
            e[3] = 0.5 * (m[7] - m[5]);
            e[4] = 0.5 * (m[2] - m[6]);
            e[5] = 0.5 * (m[3] - m[1]);
            double rotErr = Math.sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
            if (err < 1e-5 && rotErr < 1e-4) break;
            double[] p = {t[3], t[7], t[11]};
            double[][] jac = new double[6][6];
            for (int k = 0; k < 6; k++) {
                double[] a = axes[k], o = origins[k];
                double dx = p[0] - o[0], dy = p[1] - o[1], dz = p[2] - o[2];
                jac[0][k] = a[1] * dz - a[2] * dy;
                jac[1][k] = a[2] * dx - a[0] * dz;
                jac[2][k] = a[0] * dy - a[1] * dx;
                jac[3][k] = a[0];
                jac[4][k] = a[1];
                jac[5][k] = a[2];
            }
            double[] dq = dampedSolve(jac, e, 1e-4);
            for (int k = 0; k < 6; k++) q[k] = Math.max(range[k][0], Math.min(range[k][1], q[k] + dq[k]));
        }
        return err;
    }

    // (J^T J + lambda I) dq = J^T e
    private static double[] dampedSolve(double[][] j, double[] e, double lambda) {
        int n = 6;
        double[][] a = new double[n][n + 1];
        for (int r = 0; r < n; r++) {
            for (int s = 0; s < n; s++) {
                double v = 0;
                for (int k = 0; k < 6; k++) v += j[k][r] * j[k][s];
                a[r][s] = v + (r == s ? lambda : 0);
            }
            double v = 0;
            for (int k = 0; k < 6; k++) v += j[k][r] * e[k];
            a[r][n] = v;
        }
        for (int col = 0; col < n; col++) {
            int piv = col;
            for (int r = col + 1; r < n; r++) if (Math.abs(a[r][col]) > Math.abs(a[piv][col])) piv = r;
            double[] tmp = a[col];
            a[col] = a[piv];
            a[piv] = tmp;
            for (int r = col + 1; r < n; r++) {
                double f = a[r][col] / a[col][col];
                for (int s = col; s <= n; s++) a[r][s] -= f * a[col][s];
            }
        }
        double[] x = new double[n];
        for (int r = n - 1; r >= 0; r--) {
            double v = a[r][n];
            for (int s = r + 1; s < n; s++) v -= a[r][s] * x[s];
            x[r] = v / a[r][r];
        }
        return x;
    }

    private static double[] joint(double[] t, int index, int axis, double angle, double[][] axes, double[][] origins) {
        if (axes != null) {
            axes[index][0] = t[axis];
            axes[index][1] = t[4 + axis];
            axes[index][2] = t[8 + axis];
            origins[index][0] = t[3];
            origins[index][1] = t[7];
            origins[index][2] = t[11];
        }
        return mul(t, rot(axis, angle));
    }

    private static double[] identity() { return new double[]{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; }

    private static double[] trans(double x, double y, double z) { return new double[]{1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z}; }

    private static double[] rot(int axis, double a) {
        double c = Math.cos(a), s = Math.sin(a);
        return switch (axis) {
            case 0 -> new double[]{1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0};
            case 1 -> new double[]{c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0};
            default -> new double[]{c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0};
        };
    }

    private static double[] mul(double[] a, double[] b) {
        double[] o = new double[12];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 4; j++) {
                double v = a[i * 4] * b[j] + a[i * 4 + 1] * b[4 + j] + a[i * 4 + 2] * b[8 + j];
                if (j == 3) v += a[i * 4 + 3];
                o[i * 4 + j] = v;
            }
        }
        return o;
    }
}

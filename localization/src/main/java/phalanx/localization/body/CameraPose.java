package phalanx.localization.body;

import phalanx.model.robot.NaoModel;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.Vector3;
import phalanx.model.field.Vector2;

/**
 * Where the camera is and how it is turned, relative to the body at one instant, so that a polar,
 * camera-relative observation becomes a vector in the <em>level body frame</em>: origin at the torso
 * centre, +x the torso's forward direction projected on the ground, +y left, +z straight up.
 * Built from the neck joints (hj1 yaw, hj2 pitch), the torso tilt (accelerometer) and the legs
 * (forward kinematics for the height; thesis 4.6 Walk to Ball). Immutable; one per vision frame.
 */
public final class CameraPose {
    // Rotation camera -> level body frame (row-major), and the camera position in that frame.
    private final double m00, m01, m02, m10, m11, m12, m20, m21, m22;
    private final double cx, cy, cz;
    private final double torsoHeight;

    private CameraPose(double[] m, double[] c, double torsoHeight) {
        m00 = m[0]; m01 = m[1]; m02 = m[2]; m10 = m[3]; m11 = m[4]; m12 = m[5]; m20 = m[6]; m21 = m[7]; m22 = m[8];
        cx = c[0]; cy = c[1]; cz = c[2];
        this.torsoHeight = torsoHeight;
    }

    /**
     * The camera pose from the joint angles and the accelerometer reading.
     *
     * @param joints joint angles (hj1, hj2 and the leg pitch joints; missing ones count as 0)
     * @param acc    accelerometer in the torso frame the server uses (+x right, +y forward, +z up);
     *               null, non-finite or near zero means "upright"
     */
    public static CameraPose of(NaoModel body, JointAngles joints, Vector3 acc) {
        double yaw = angle(joints, Joint.HJ1), pitch = angle(joints, Joint.HJ2);
        // Body frame: +x forward, +y left, +z up (server torso frame: x right, y forward).
        double[] tilt = levelRotation(acc);
        // Head in the body frame: yaw about +z at the neck, then pitch about the torso's right axis
        // (-y here); positive hj2 lifts the view (ODE hinge sign, axis +x of the server torso frame).
        double cyaw = Math.cos(yaw), syaw = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
        // R_head = Rz(yaw) * Ry(-pitch)
        double[] head = {
                cyaw * cp, -syaw, -cyaw * sp,
                syaw * cp, cyaw, -syaw * sp,
                sp, 0, cp};
        // Camera position: neck, up to the pitch axis, then the head centre 0.005 above that axis, turned.
        double axis = NaoModel.NECK_ABOVE_TORSO + NaoModel.HEAD_ABOVE_NECK - NaoModel.PITCH_AXIS_BELOW_HEAD;
        double r = NaoModel.PITCH_AXIS_BELOW_HEAD;
        double[] camBody = {head[2] * r, head[5] * r, axis + head[8] * r};
        double[] m = mul(tilt, head);
        double[] c = apply(tilt, camBody);
        // Torso height: the lower of the two soles in the level frame carries the robot.
        double best = Double.NEGATIVE_INFINITY;
        for (int leg = 0; leg < 2; leg++) {
            double[] s = body.soleInTorso(joints, leg == 0);
            best = Math.max(best, -heightOf(tilt, s[0], 0, s[1]));   // z of apply(tilt, {s[0], 0, s[1]})
        }
        return new CameraPose(m, c, best);
    }

    /** Upright camera with the head turned by yaw and pitch (degrees): for tests and simple callers. */
    public static CameraPose upright(NaoModel body, double yawDeg, double pitchDeg) {
        double[] d = new double[Joint.COUNT];
        d[Joint.HJ1.ordinal()] = yawDeg;
        d[Joint.HJ2.ordinal()] = pitchDeg;
        return of(body, new JointAngles(d), null);
    }

    /** The observation as a vector in the level body frame (metres from the torso centre). */
    public Vector3 toBody(Polar p) {
        double h = Math.toRadians(p.horizontalDeg()), v = Math.toRadians(p.verticalDeg());
        double cv = Math.cos(v);
        double x = p.distance() * cv * Math.cos(h), y = p.distance() * cv * Math.sin(h), z = p.distance() * Math.sin(v);
        return new Vector3(cx + m00 * x + m01 * y + m02 * z, cy + m10 * x + m11 * y + m12 * z, cz + m20 * x + m21 * y + m22 * z);
    }

    /**
     * The x and y of {@link #toBody} (the observation on the ground plane of the level body frame)
     * without the Vector3: the belief store places every seen landmark, ball and body part so.
     */
    public Vector2 toGround(Polar p) {
        double h = Math.toRadians(p.horizontalDeg()), v = Math.toRadians(p.verticalDeg());
        double cv = Math.cos(v);
        double x = p.distance() * cv * Math.cos(h), y = p.distance() * cv * Math.sin(h), z = p.distance() * Math.sin(v);
        return new Vector2(cx + m00 * x + m01 * y + m02 * z, cy + m10 * x + m11 * y + m12 * z);
    }

    /**
     * Whether a point on the ground (level body frame, height z above the ground) lies within halfAngleDeg of the
     * camera's axis both horizontally and vertically: the inverse of {@link #toBody}, for the server's square view cone.
     */
    public boolean inView(Vector2 ground, double z, double halfAngleDeg) {
        double dx = ground.x() - cx, dy = ground.y() - cy, dz = z - torsoHeight - cz;
        // camera frame = M^T (p - c)
        double x = m00 * dx + m10 * dy + m20 * dz, y = m01 * dx + m11 * dy + m21 * dz, w = m02 * dx + m12 * dy + m22 * dz;
        if (x <= 0) return false;
        double limit = Math.toRadians(halfAngleDeg);
        return Math.abs(Math.atan2(y, x)) <= limit && Math.abs(Math.atan2(w, Math.hypot(x, y))) <= limit;
    }

    /** Height of the torso centre above the ground (forward kinematics of the supporting leg). */
    public double torsoHeight() { return torsoHeight; }

    /** Height of the camera above the ground. */
    public double cameraHeight() { return torsoHeight + cz; }

    /**
     * Thesis 4.6 Walk to Ball: the ground distance from the body to an object on the ground, from
     * the camera distance and the camera height (Pythagoras; the thesis prints a plus sign, the
     * geometry needs the difference).
     */
    public double groundDistance(double cameraDistance, double objectHeight) {
        double dz = cameraHeight() - objectHeight;
        double g2 = cameraDistance * cameraDistance - dz * dz;
        return g2 > 0 ? Math.sqrt(g2) : 0;
    }

    private static double angle(JointAngles j, Joint joint) {
        if (j == null || !j.has(joint)) return 0;
        double r = j.radians(joint);
        return Double.isFinite(r) ? r : 0;
    }

    /**
     * The rotation body -> level frame: the smallest rotation that turns the measured "up"
     * (the accelerometer's reading of gravity) onto +z, so the heading is the torso's forward
     * direction projected on the ground.
     */
    static double[] levelRotation(Vector3 acc) {
        if (acc == null || !acc.isFinite()) return identity();
        double ux = acc.y(), uy = -acc.x(), uz = acc.z();   // server torso frame -> body frame
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        if (n < 1.0) return identity();                      // no gravity reading (first messages)
        ux /= n; uy /= n; uz /= n;
        // Rodrigues: axis = u x z = (uy, -ux, 0), cos = uz.
        double ax = uy, ay = -ux, s = Math.sqrt(ax * ax + ay * ay), c = uz;
        if (s < 1e-9) {
            if (c > 0) return identity();
            return new double[] {1, 0, 0, 0, -1, 0, 0, 0, -1};  // upside down: turn about x
        }
        ax /= s; ay /= s;
        double t = 1 - c;
        return new double[] {
                t * ax * ax + c, t * ax * ay, ay * s,
                t * ax * ay, t * ay * ay + c, -ax * s,
                -ay * s, ax * s, c};
    }

    private static double[] mul(double[] a, double[] b) {
        double[] r = new double[9];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
        return r;
    }

    private static double[] identity() { return new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

    /** The z row of {@link #apply}: m applied to (x, y, z), without the vectors (twice per vision frame). */
    private static double heightOf(double[] m, double x, double y, double z) { return m[6] * x + m[7] * y + m[8] * z; }

    private static double[] apply(double[] m, double[] v) {
        return new double[] {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
                m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
    }
}

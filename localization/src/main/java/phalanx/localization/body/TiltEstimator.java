package phalanx.localization.body;

import phalanx.comm.perception.Vector3;

/**
 * The direction of "up" in the torso frame, for the camera pose: the gyro integrated every cycle,
 * pulled gently toward the accelerometer whenever it reads about 1 g. The accelerometer alone is
 * wrong while the body rotates fast: in S3, tipping backwards at 30-160 °/s, it reports the torso
 * leaning forwards while the torso leans 20° back, and a fix made with it is 2 m off.
 * Server torso frame: +x right, +y forward, +z up. No allocation per cycle.
 */
public final class TiltEstimator {
    private static final double G = 9.81;
    private final double accWeight, accTolerance;
    private double ux, uy, uz = 1;
    private boolean started;

    /**
     * @param accWeight    share of the accelerometer's direction mixed in per cycle (0..1]
     * @param accTolerance m/s² around 1 g within which the accelerometer is trusted
     */
    public TiltEstimator(double accWeight, double accTolerance) {
        this.accWeight = accWeight;
        this.accTolerance = accTolerance;
    }

    /** One cycle: gyro in °/s (may be null), accelerometer in m/s² (may be null), dt seconds. */
    public void update(Vector3 gyro, Vector3 acc, double dt) {
        if (gyro != null && gyro.isFinite() && dt > 0 && dt < 0.5) {
            // A fixed world vector seen from a frame turning at w moves as du/dt = -w x u.
            double wx = Math.toRadians(gyro.x()) * dt, wy = Math.toRadians(gyro.y()) * dt, wz = Math.toRadians(gyro.z()) * dt;
            double nx = ux - (wy * uz - wz * uy), ny = uy - (wz * ux - wx * uz), nz = uz - (wx * uy - wy * ux);
            ux = nx; uy = ny; uz = nz;
        }
        if (acc != null && acc.isFinite()) {
            double n = acc.norm();
            if (Math.abs(n - G) < accTolerance) {
                double k = started ? accWeight : 1;      // the first good reading sets the tilt
                ux = (1 - k) * ux + k * acc.x() / n;
                uy = (1 - k) * uy + k * acc.y() / n;
                uz = (1 - k) * uz + k * acc.z() / n;
                started = true;
            }
        }
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        if (n > 1e-9) { ux /= n; uy /= n; uz /= n; } else { ux = 0; uy = 0; uz = 1; }
    }

    /**
     * The torso's turn rate about the vertical, °/s (positive: to the left): the gyro's rates (torso frame, °/s)
     * along the estimated "up". Upright this is the gyro's z; NaN without a finite reading. No allocation.
     */
    public double turnRateDeg(Vector3 gyro) {
        if (gyro == null || !gyro.isFinite()) return Double.NaN;
        return gyro.x() * ux + gyro.y() * uy + gyro.z() * uz;
    }

    /** "Up" in the torso frame as a unit vector scaled to 9.81 (the shape of an accelerometer reading). */
    public Vector3 up() { return new Vector3(ux * G, uy * G, uz * G); }

    /** The angle between the torso's up axis and the vertical, degrees. */
    public double tiltDeg() { return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, uz)))); }
}

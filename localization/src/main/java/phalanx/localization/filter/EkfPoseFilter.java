package phalanx.localization.filter;

import phalanx.localization.LocalizationConfig;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.localization.vision.LandmarkSighting;
import phalanx.localization.vision.SelfLocalizer;

import java.util.List;

/**
 * Beyond the thesis (its future work asks for a probabilistic localization): an extended Kalman
 * filter over (x, y, theta). Prediction: the walk's odometry plus process noise every cycle.
 * Correction: every seen landmark on its own (so one landmark helps too), the measurement being
 * the landmark's ground vector in the body frame; a Mahalanobis gate drops outliers. Started from
 * the pair-triangulation fix. Re-started from the fix of a single frame that disagrees with the belief (every
 * landmark outside the gate and the fix farther than {@code relocateMetres}/{@code relocateDeg}) while its
 * landmarks agree with that fix ({@link SelfLocalizer#consistent}, {@code relocateResidual*}; issue 19).
 * Otherwise re-started from the mean of their fixes (relocation, issue 19) after
 * {@code relocateFrames} vision frames in a row that disagree with the belief: every landmark outside
 * the gate and the fix farther than {@code relocateMetres}/{@code relocateDeg} from the belief, each
 * fix within {@code relocateSpread*} of the one before (beam, trainer or referee move). A frame whose fix
 * is near the belief, or with a landmark inside the gate, ends the count; a frame without a fix leaves
 * it. Plain doubles, no allocation per cycle.
 */
public final class EkfPoseFilter implements PoseFilter {
    /** chi-square, 2 degrees of freedom, 99.9 %. */
    private static final double GATE = 13.8;
    /** Vision noise model: sigma along the sight line and across it, plus a floor for the camera offset. */
    private static final double SIGMA_FLOOR = 0.02, SIGMA_ALONG = 0.004, SIGMA_ACROSS_RAD = Math.toRadians(0.4);

    private final double qPos, qAng;
    private final int relocateFrames;
    private final double relocateMetres, relocateDeg, spreadMetres, spreadDeg, residualMetres, residualShare;
    private boolean valid;
    private double x, y, t;                       // t in radians
    private double p00, p01, p02, p11, p12, p22;  // symmetric covariance
    private int badFrames, starts;
    private double lastBadX, lastBadY, lastBadDeg; // the previous disagreeing frame's fix
    private double sumX, sumY, sumC, sumS;         // sums over the disagreeing frames' fixes (heading as cos, sin)

    public EkfPoseFilter(LocalizationConfig c) {
        qPos = c.ekfPositionNoise() * c.ekfPositionNoise();
        double a = Math.toRadians(c.ekfAngleNoiseDeg());
        qAng = a * a;
        relocateFrames = c.relocateFrames();
        relocateMetres = c.relocateMetres();
        relocateDeg = c.relocateDeg();
        spreadMetres = c.relocateSpreadMetres();
        spreadDeg = c.relocateSpreadDeg();
        residualMetres = c.relocateResidualMetres();
        residualShare = c.relocateResidualShare();
    }

    @Override public void predict(double forward, double left, double turnDeg) {
        if (!valid) return;
        double c = Math.cos(t), s = Math.sin(t);
        x += c * forward - s * left;
        y += s * forward + c * left;
        t = Math.toRadians(Angles.normalize(Math.toDegrees(t) + turnDeg));
        // Jacobian of the motion with respect to theta: F = [1 0 a; 0 1 b; 0 0 1].
        double a = -s * forward - c * left, b = c * forward - s * left;
        double n00 = p00 + 2 * a * p02 + a * a * p22, n01 = p01 + a * p12 + b * p02 + a * b * p22;
        double n11 = p11 + 2 * b * p12 + b * b * p22, n02 = p02 + a * p22, n12 = p12 + b * p22;
        p00 = n00 + qPos; p01 = n01; p11 = n11 + qPos; p02 = n02; p12 = n12; p22 += qAng;
    }

    @Override public boolean update(Pose2 fix, List<LandmarkSighting> seen) {
        if (!valid) {
            if (fix == null) return false;
            start(fix);
            return true;
        }
        boolean far = fix != null && (Math.hypot(fix.x() - x, fix.y() - y) > relocateMetres
                || Math.abs(Angles.difference(fix.thetaDeg(), Math.toDegrees(t))) > relocateDeg);
        if (far && !anyInGate(seen)) {
            // Every landmark agrees with the frame's own fix: a move, followed at once (issue 19).
            if (SelfLocalizer.consistent(fix, seen, residualMetres, residualShare)) {
                start(fix);
                for (int k = 0; k < seen.size(); k++) correct(seen.get(k), true);   // and this frame's landmarks
                return true;
            }
            // The whole frame disagrees with the belief: count it towards a relocation, change nothing.
            boolean near = badFrames > 0 && Math.hypot(fix.x() - lastBadX, fix.y() - lastBadY) <= spreadMetres
                    && Math.abs(Angles.difference(fix.thetaDeg(), lastBadDeg)) <= spreadDeg;
            badFrames = near ? badFrames + 1 : 1;
            if (badFrames == 1) sumX = sumY = sumC = sumS = 0;
            lastBadX = fix.x();
            lastBadY = fix.y();
            lastBadDeg = fix.thetaDeg();
            sumX += fix.x();
            sumY += fix.y();
            sumC += Math.cos(Math.toRadians(fix.thetaDeg()));
            sumS += Math.sin(Math.toRadians(fix.thetaDeg()));
            if (badFrames < relocateFrames) return false;
            // Re-initialised at the mean of the disagreeing frames' fixes (they agree with each other).
            start(new Pose2(sumX / badFrames, sumY / badFrames, Math.toDegrees(Math.atan2(sumS, sumC))));
            return true;
        }
        if (fix != null) badFrames = 0;   // the fix agrees with the belief (or a landmark does)
        int used = 0;
        for (int k = 0; k < seen.size(); k++) if (correct(seen.get(k), true)) used++;
        if (used > 0) badFrames = 0;
        return used > 0;
    }

    private boolean anyInGate(List<LandmarkSighting> seen) {
        for (int k = 0; k < seen.size(); k++) if (correct(seen.get(k), false)) return true;
        return false;
    }

    private void start(Pose2 fix) {
        valid = true;
        starts++;
        badFrames = 0;
        x = fix.x();
        y = fix.y();
        t = Math.toRadians(fix.thetaDeg());
        p00 = p11 = 0.3 * 0.3;
        p22 = Math.toRadians(10) * Math.toRadians(10);
        p01 = p02 = p12 = 0;
    }

    /**
     * One landmark: z = R(-t) (L - p), measured as the sighting's relative vector. Returns whether it
     * passes the gate; only with {@code apply} does it correct the state.
     */
    private boolean correct(LandmarkSighting l, boolean apply) {
        double c = Math.cos(t), s = Math.sin(t);
        double dx = l.position().x() - x, dy = l.position().y() - y;
        double h1 = c * dx + s * dy, h2 = -s * dx + c * dy;
        double z1 = l.relative().x(), z2 = l.relative().y();
        double r = Math.hypot(z1, z2);
        if (!(r > 0)) return false;
        // H rows: d h1 = [-c, -s, h2], d h2 = [s, -c, -h1].
        double a0 = -c, a1 = -s, a2 = h2, b0 = s, b1 = -c, b2 = -h1;
        // Measurement noise in the body frame: along / across the sight line.
        double sa = SIGMA_FLOOR + SIGMA_ALONG * r, sc = SIGMA_FLOOR + SIGMA_ACROSS_RAD * r;
        double ux = z1 / r, uy = z2 / r, va = sa * sa, vc = sc * sc;
        double r00 = va * ux * ux + vc * uy * uy, r01 = (va - vc) * ux * uy, r11 = va * uy * uy + vc * ux * ux;
        // P H^T (3x2)
        double ph00 = p00 * a0 + p01 * a1 + p02 * a2, ph01 = p00 * b0 + p01 * b1 + p02 * b2;
        double ph10 = p01 * a0 + p11 * a1 + p12 * a2, ph11 = p01 * b0 + p11 * b1 + p12 * b2;
        double ph20 = p02 * a0 + p12 * a1 + p22 * a2, ph21 = p02 * b0 + p12 * b1 + p22 * b2;
        // S = H P H^T + R (2x2)
        double s00 = a0 * ph00 + a1 * ph10 + a2 * ph20 + r00;
        double s01 = a0 * ph01 + a1 * ph11 + a2 * ph21 + r01;
        double s11 = b0 * ph01 + b1 * ph11 + b2 * ph21 + r11;
        double det = s00 * s11 - s01 * s01;
        if (!(det > 0)) return false;
        double i00 = s11 / det, i01 = -s01 / det, i11 = s00 / det;
        double e1 = z1 - h1, e2 = z2 - h2;
        double d2 = e1 * (i00 * e1 + i01 * e2) + e2 * (i01 * e1 + i11 * e2);
        if (!(d2 <= GATE)) return false;
        if (!apply) return true;
        // K = P H^T S^-1 (3x2)
        double k00 = ph00 * i00 + ph01 * i01, k01 = ph00 * i01 + ph01 * i11;
        double k10 = ph10 * i00 + ph11 * i01, k11 = ph10 * i01 + ph11 * i11;
        double k20 = ph20 * i00 + ph21 * i01, k21 = ph20 * i01 + ph21 * i11;
        x += k00 * e1 + k01 * e2;
        y += k10 * e1 + k11 * e2;
        t = Math.toRadians(Angles.normalize(Math.toDegrees(t + k20 * e1 + k21 * e2)));
        // P = P - K H P = P - K (P H^T)^T
        double n00 = p00 - (k00 * ph00 + k01 * ph01), n01 = p01 - (k00 * ph10 + k01 * ph11), n02 = p02 - (k00 * ph20 + k01 * ph21);
        double n11 = p11 - (k10 * ph10 + k11 * ph11), n12 = p12 - (k10 * ph20 + k11 * ph21);
        double n22 = p22 - (k20 * ph20 + k21 * ph21);
        p00 = n00; p01 = n01; p02 = n02; p11 = n11; p12 = n12; p22 = n22;
        return true;
    }

    @Override public Pose2 pose() { return valid ? new Pose2(x, y, Math.toDegrees(t)) : null; }

    /** exp(-sigma / 0.3 m) of the position's standard deviation. */
    @Override public double confidence() {
        return valid ? Math.exp(-Math.sqrt(Math.max(0, p00 + p11)) / 0.3) : 0;
    }

    /** Standard deviation of the position, metres (NaN before the first fix). */
    public double positionSigma() { return valid ? Math.sqrt(Math.max(0, p00 + p11)) : Double.NaN; }

    @Override public int starts() { return starts; }

    @Override public void reset() {
        valid = false;
        badFrames = 0;
    }
}

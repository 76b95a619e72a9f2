package phalanx.localization.vision;

import phalanx.localization.LocalizationConfig;
import phalanx.model.field.Angles;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * Thesis 4.4.1, self-localization by landmark pairs: for every pair of visible landmarks, intersect
 * the two circles centred on the landmarks (radius = the seen ground distance), keep the candidate
 * whose landmark bearings agree and that lies on the field, derive the body orientation from the
 * bearings, and average over the pairs. Fewer than two landmarks: no fix (null).
 */
public final class SelfLocalizer {
    private final FieldSpec field;
    private final LocalizationConfig config;

    public SelfLocalizer(FieldSpec field, LocalizationConfig config) {
        this.field = field;
        this.config = config;
    }

    /** The averaged fix from every usable pair, or null when no pair gives one. */
    public Pose2 locate(List<LandmarkSighting> seen) {
        int n = seen.size();
        if (n < 2) return null;
        double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                LandmarkSighting a = seen.get(i), b = seen.get(j);
                Pose2 p = pair(a, b);
                if (p == null) continue;
                double w = 1;
                if (config.pairWeighting() == LocalizationConfig.PairWeighting.GEOMETRY) {
                    // Error of a circle intersection grows as 1/sin(angle between the sight lines).
                    double sin = Math.abs(a.relative().cross(b.relative())) / (a.relative().norm() * b.relative().norm());
                    w = sin * sin + 1e-6;
                }
                sw += w;
                sx += w * p.x();
                sy += w * p.y();
                double t = Math.toRadians(p.thetaDeg());
                sc += w * Math.cos(t);
                ss += w * Math.sin(t);
            }
        }
        if (sw == 0) return null;
        return new Pose2(sx / sw, sy / sw, Math.toDegrees(Math.atan2(ss, sc)));
    }

    /** The fix from one pair, or null when the circles do not meet or no candidate fits. */
    public Pose2 pair(LandmarkSighting a, LandmarkSighting b) {
        Vector2 pa = a.position(), pb = b.position();
        double ra = a.relative().norm(), rb = b.relative().norm();
        double d = pa.distanceTo(pb);
        if (d < 1e-6 || !(ra > 0) || !(rb > 0)) return null;
        double along = (ra * ra - rb * rb + d * d) / (2 * d);
        double h2 = ra * ra - along * along;
        // Noise can pull two nearly tangent circles apart: accept a small gap, reject a real one.
        if (h2 < 0) {
            if (h2 < -0.04 * ra * ra) return null;
            h2 = 0;
        }
        double h = Math.sqrt(h2);
        double ux = (pb.x() - pa.x()) / d, uy = (pb.y() - pa.y()) / d;
        double mx = pa.x() + along * ux, my = pa.y() + along * uy;
        Pose2 best = null;
        double bestErr = Double.POSITIVE_INFINITY;
        for (int sign = -1; sign <= 1; sign += 2) {
            double cx = mx - sign * h * uy, cy = my + sign * h * ux;   // the candidate position
            if (!field.contains(cx, cy, config.fieldMarginMetres())) continue;
            // Body orientation that makes each landmark appear at its seen bearing.
            double ta = Angles.normalize(bearingDeg(cx, cy, pa) - a.relative().angleDeg());
            double tb = Angles.normalize(bearingDeg(cx, cy, pb) - b.relative().angleDeg());
            double err = Math.abs(Angles.difference(ta, tb));
            if (err < bestErr) {
                bestErr = err;
                best = new Pose2(cx, cy, Angles.normalize(tb + Angles.difference(ta, tb) / 2));
            }
            if (h == 0) break;
        }
        // The right candidate sees both landmarks at their seen bearings; a mirror image does not.
        return bestErr <= 20 ? best : null;
    }

    /**
     * Whether the frame's landmarks agree with each other (issue 19, not in the thesis): at least two, and each
     * seen ground vector within {@code metres + share * distance} of where the fix puts that landmark. A fix from
     * consistent landmarks is what a move shows; a wrong camera pose (tilt, a mirrored pair) does not fit them all.
     * NaN thresholds: never. No allocation.
     */
    public static boolean consistent(Pose2 fix, List<LandmarkSighting> seen, double metres, double share) {
        if (fix == null || seen.size() < 2) return false;
        double r = Math.toRadians(fix.thetaDeg()), c = Math.cos(r), s = Math.sin(r);
        for (int k = 0; k < seen.size(); k++) {
            LandmarkSighting l = seen.get(k);
            double dx = l.position().x() - fix.x(), dy = l.position().y() - fix.y();
            double ex = l.relative().x() - (c * dx + s * dy), ey = l.relative().y() - (-s * dx + c * dy);
            double tol = metres + share * Math.hypot(l.relative().x(), l.relative().y());
            if (!(Math.hypot(ex, ey) <= tol)) return false;
        }
        return true;
    }

    /** to.minus(new Vector2(x, y)).angleDeg() without the vectors (every landmark pair of every frame). */
    private static double bearingDeg(double x, double y, Vector2 to) {
        return Math.toDegrees(Math.atan2(to.y() - y, to.x() - x));
    }
}

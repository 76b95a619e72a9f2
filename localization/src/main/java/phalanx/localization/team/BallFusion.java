package phalanx.localization.team;

import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;

/**
 * Thesis 5.4, the coordinator's global ball belief: observations are clustered in arrival order
 * (an observation joins the largest cluster whose representative lies within the threshold,
 * otherwise it starts a cluster; the representative is the cluster's mean), each cluster weighs
 * |s|^k (k = 3), and the belief is the weighted mean of the representatives.
 * Also infers where a "type B" player stands (it reports only the ball relative to itself).
 */
public final class BallFusion {
    private final double threshold, exponent;

    public BallFusion(double clusterMetres, double weightExponent) {
        if (!(clusterMetres > 0)) throw new IllegalArgumentException("cluster threshold must be positive");
        this.threshold = clusterMetres;
        this.exponent = weightExponent;
    }

    /** The fused ball position, or null when there is no usable observation (null or non-finite ones are skipped). */
    public Vector2 fuse(List<Vector2> observations) {
        List<double[]> clusters = new ArrayList<>();   // {sumX, sumY, count}
        for (Vector2 o : observations) {
            if (o == null || !o.isFinite()) continue;
            double[] best = null;
            for (double[] c : clusters) {
                double mx = c[0] / c[2], my = c[1] / c[2];
                if (Math.hypot(o.x() - mx, o.y() - my) < threshold && (best == null || c[2] > best[2])) best = c;
            }
            if (best == null) clusters.add(new double[] {o.x(), o.y(), 1});
            else { best[0] += o.x(); best[1] += o.y(); best[2]++; }
        }
        if (clusters.isEmpty()) return null;
        double sw = 0, sx = 0, sy = 0;
        for (double[] c : clusters) {
            double w = Math.pow(c[2], exponent);
            sw += w;
            sx += w * c[0] / c[2];
            sy += w * c[1] / c[2];
        }
        return new Vector2(sx / sw, sy / sw);
    }

    /**
     * Where a type-B player stands: the fused ball minus its report. The report is the ball's
     * distance and direction from the player; the direction must be in the team's frame (a player
     * that only knows a body-relative bearing has to add its heading belief first; thesis 5.4 leaves
     * this open). Null for a bad report.
     */
    public static Vector2 typeBPosition(Vector2 globalBall, double ballDistance, double directionDeg) {
        if (globalBall == null || !(ballDistance >= 0) || !Double.isFinite(ballDistance) || !Double.isFinite(directionDeg))
            return null;
        return globalBall.minus(Vector2.polar(ballDistance, directionDeg));
    }
}

package phalanx.coordination.beliefs;

import java.util.List;
import phalanx.localization.field.Vector2;

/**
 * The global ball from several players' observations (thesis 5.4, Figure 5.3). Observations are
 * clustered in arrival order: each joins the largest cluster whose mean lies within the threshold
 * (ties: the first such cluster), or starts a new one. The ball is the mean of the cluster means,
 * each weighted by its size to the given power (|s|^3 in the thesis), so a few outliers barely move it.
 */
public final class BallFusion {
    private BallFusion() {}

    /** The fused ball, or null when there is no observation. */
    public static Vector2 fuse(List<Vector2> observations, double threshold, double exponent) {
        int n = observations.size();
        if (n == 0) return null;
        double[] sx = new double[n], sy = new double[n];
        int[] size = new int[n];
        int clusters = 0;
        for (Vector2 o : observations) {
            int best = -1;
            for (int c = 0; c < clusters; c++) {
                double mx = sx[c] / size[c], my = sy[c] / size[c];
                if (Math.hypot(o.x() - mx, o.y() - my) < threshold && (best < 0 || size[c] > size[best])) best = c;
            }
            if (best < 0) best = clusters++;
            sx[best] += o.x();
            sy[best] += o.y();
            size[best]++;
        }
        double wx = 0, wy = 0, wsum = 0;
        for (int c = 0; c < clusters; c++) {
            double w = Math.pow(size[c], exponent);
            wx += w * sx[c] / size[c];
            wy += w * sy[c] / size[c];
            wsum += w;
        }
        return new Vector2(wx / wsum, wy / wsum);
    }
}

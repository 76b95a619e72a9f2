package phalanx.coordination.support;

import java.util.Arrays;

/**
 * A second support mapper, beyond the thesis: the "minimum maximal distance, then minimum sum of squared
 * distances" assignment of UT Austin Villa's SCRAM role assignment (MacAlpine, Price, Stone, AAAI 2015).
 * First the bottleneck: the smallest distance T such that every player can be matched to a position no
 * farther than T (binary search over the n² distances, each step a bipartite matching, O(n³ log n)).
 * Then, among the mappings that use no longer edge, the one with the least sum of squared distances
 * (Hungarian algorithm, O(n³)). SCRAM's guarantee is about time, not geometry: players that set off
 * together at the same speed on these routes never reach a crossing point together, so routes may cross
 * but players do not meet (the paper proves it for its assignments). It ignores {@link SupportCost}'s
 * collision feature; the cost it reports is the thesis's cost of the mapping it picks, for comparison.
 * The bottleneck step is here a threshold on the plain MSD² problem, not the paper's recursive
 * refinement, so the second-longest distance and below are only minimised through the sum of squares.
 */
public final class ScramSupportMapper implements SupportMapper {
    private final boolean minimalMakespan;

    /** MMD+MSD²: the least longest distance first, then the least sum of squares. */
    public ScramSupportMapper() { this(true); }

    /** @param minimalMakespan false for plain MSD² (least sum of squared distances, no bottleneck step) */
    public ScramSupportMapper(boolean minimalMakespan) { this.minimalMakespan = minimalMakespan; }

    @Override
    public SupportMapping map(SupportCost cost) {
        int n = cost.size();
        if (n == 0) return new SupportMapping(new int[0], 0, 0);
        if (!minimalMakespan) {
            double[][] w = new double[n][n];
            for (int a = 0; a < n; a++) for (int p = 0; p < n; p++) w[a][p] = cost.distance(a, p) * cost.distance(a, p);
            int[] positionOf = hungarian(w);
            return new SupportMapping(positionOf, cost.total(positionOf), 0);
        }
        double[] sorted = new double[n * n];
        for (int a = 0; a < n; a++) for (int p = 0; p < n; p++) sorted[a * n + p] = cost.distance(a, p);
        Arrays.sort(sorted);
        int lo = n - 1, hi = n * n - 1;            // at least n edges are needed for a perfect matching
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (perfectMatching(cost, sorted[mid])) hi = mid; else lo = mid + 1;
        }
        double bottleneck = sorted[lo];
        double forbidden = 1e12;
        double[][] w = new double[n][n];
        for (int a = 0; a < n; a++) for (int p = 0; p < n; p++) {
            double d = cost.distance(a, p);
            w[a][p] = d <= bottleneck ? d * d : forbidden;
        }
        int[] positionOf = hungarian(w);
        return new SupportMapping(positionOf, cost.total(positionOf), 0);
    }

    /** True when every player can be matched to its own position no farther than the limit (Kuhn). */
    static boolean perfectMatching(SupportCost cost, double limit) {
        int n = cost.size();
        int[] ownerOf = new int[n];
        Arrays.fill(ownerOf, -1);
        for (int a = 0; a < n; a++) {
            if (!augment(cost, limit, a, new boolean[n], ownerOf)) return false;
        }
        return true;
    }

    private static boolean augment(SupportCost cost, double limit, int a, boolean[] seen, int[] ownerOf) {
        int n = cost.size();
        for (int p = 0; p < n; p++) {
            if (seen[p] || cost.distance(a, p) > limit) continue;
            seen[p] = true;
            if (ownerOf[p] < 0 || augment(cost, limit, ownerOf[p], seen, ownerOf)) {
                ownerOf[p] = a;
                return true;
            }
        }
        return false;
    }

    /** Minimum-cost perfect assignment of rows to columns (Hungarian algorithm with potentials, O(n³)). */
    static int[] hungarian(double[][] w) {
        int n = w.length;
        double[] u = new double[n + 1], v = new double[n + 1], minv = new double[n + 1];
        int[] p = new int[n + 1], way = new int[n + 1];
        boolean[] used = new boolean[n + 1];
        for (int i = 1; i <= n; i++) {
            p[0] = i;
            int j0 = 0;
            Arrays.fill(minv, Double.POSITIVE_INFINITY);
            Arrays.fill(used, false);
            do {
                used[j0] = true;
                int i0 = p[j0], j1 = 0;
                double delta = Double.POSITIVE_INFINITY;
                for (int j = 1; j <= n; j++) {
                    if (used[j]) continue;
                    double cur = w[i0 - 1][j - 1] - u[i0] - v[j];
                    if (cur < minv[j]) { minv[j] = cur; way[j] = j0; }
                    if (minv[j] < delta) { delta = minv[j]; j1 = j; }
                }
                for (int j = 0; j <= n; j++) {
                    if (used[j]) { u[p[j]] += delta; v[j] -= delta; } else minv[j] -= delta;
                }
                j0 = j1;
            } while (p[j0] != 0);
            do { int j1 = way[j0]; p[j0] = p[j1]; j0 = j1; } while (j0 != 0);
        }
        int[] rowToCol = new int[n];
        for (int j = 1; j <= n; j++) rowToCol[p[j] - 1] = j - 1;
        return rowToCol;
    }
}

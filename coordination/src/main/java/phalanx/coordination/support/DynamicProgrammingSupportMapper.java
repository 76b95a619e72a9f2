package phalanx.coordination.support;

/**
 * Algorithm 5 (thesis 5.12, after UT Austin Villa): for k = 1..n, every player α is tried on position P_k
 * together with the best mapping already found for each set s of k−1 other players onto P_1..P_{k−1};
 * the cheapest mapping per set {α} ∪ s is kept. That is n·2^(n−1) evaluations (1,024 for 8, 5,120 for 10)
 * instead of n!. Sets are bit masks visited in increasing order, so a set's best mapping is final before
 * it is extended. Exact when the cost is separable (collision weight 0); with collisions it is a
 * heuristic, as the thesis says.
 */
public final class DynamicProgrammingSupportMapper implements SupportMapper {

    @Override
    public SupportMapping map(SupportCost cost) {
        int n = cost.size();
        if (n == 0) return new SupportMapping(new int[0], 0, 0);
        int full = (1 << n) - 1;
        double[] best = new double[1 << n];
        byte[] last = new byte[1 << n];
        java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
        best[0] = 0;
        boolean collisions = cost.collisionWeight() != 0;
        long evaluated = 0;
        for (int m = 0; m < full; m++) {
            double base = best[m];
            int k = Integer.bitCount(m);           // the new player takes position P_{k+1} (index k)
            for (int a = 0; a < n; a++) {
                if ((m >>> a & 1) != 0) continue;
                double c = base + cost.single(a, k);
                if (collisions) {
                    for (int mm = m; mm != 0; ) {
                        int b = last[mm];
                        int q = Integer.bitCount(mm) - 1;
                        c += cost.pairCost(a, k, b, q);
                        mm &= ~(1 << b);
                    }
                }
                evaluated++;
                int nm = m | 1 << a;
                if (c < best[nm]) { best[nm] = c; last[nm] = (byte) a; }
            }
        }
        int[] positionOf = new int[n];
        for (int mm = full; mm != 0; ) {
            int b = last[mm];
            positionOf[b] = Integer.bitCount(mm) - 1;
            mm &= ~(1 << b);
        }
        return new SupportMapping(positionOf, best[full], evaluated);
    }
}

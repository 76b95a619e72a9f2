package phalanx.coordination.support;

/**
 * The exact optimum over all n! mappings, by depth-first search that abandons a partial mapping as soon as
 * it costs more than the best complete one (every term of the cost is non-negative for non-negative
 * weights). The reference the other mappers are checked and measured against; too slow for the game
 * beyond about eight players.
 */
public final class ExhaustiveSupportMapper implements SupportMapper {

    @Override
    public SupportMapping map(SupportCost cost) {
        int n = cost.size();
        Search s = new Search(cost);
        s.extend(0, 0);
        return new SupportMapping(s.best, n == 0 ? 0 : s.bestCost, s.complete);
    }

    private static final class Search {
        final SupportCost cost;
        final int n;
        final int[] cur, best;
        final boolean[] used;
        double bestCost = Double.POSITIVE_INFINITY;
        long complete;

        Search(SupportCost cost) {
            this.cost = cost;
            n = cost.size();
            cur = new int[n];
            best = new int[n];
            used = new boolean[n];
        }

        void extend(int a, double c) {
            if (c >= bestCost) return;
            if (a == n) {
                complete++;
                bestCost = c;
                System.arraycopy(cur, 0, best, 0, n);
                return;
            }
            for (int p = 0; p < n; p++) {
                if (used[p]) continue;
                double add = cost.single(a, p);
                for (int b = 0; b < a; b++) add += cost.pairCost(a, p, b, cur[b]);
                used[p] = true;
                cur[a] = p;
                extend(a + 1, c + add);
                used[p] = false;
            }
        }
    }
}

package phalanx.coordination.support;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.CollisionConfig;
import phalanx.coordination.CoordinationConfig.SupportWeights;
import phalanx.model.field.Vector2;

class SupportMapperTest {
    private static final CollisionConfig C = CollisionConfig.THESIS;

    static List<Vector2> randomPoints(Random rnd, int n) {
        List<Vector2> l = new ArrayList<>(n);
        for (int i = 0; i < n; i++) l.add(new Vector2(rnd.nextDouble() * 30 - 15, rnd.nextDouble() * 20 - 10));
        return l;
    }

    static SupportCost instance(Random rnd, int n, SupportWeights w) {
        return new SupportCost(randomPoints(rnd, n), randomPoints(rnd, n), randomPoints(rnd, 3), randomPoints(rnd, 3), w, C);
    }

    /** Every permutation, by Heap's algorithm, scored with SupportCost.total. */
    static double bruteForce(SupportCost cost) {
        int n = cost.size();
        int[] p = new int[n];
        for (int i = 0; i < n; i++) p[i] = i;
        double best = cost.total(p);
        int[] c = new int[n];
        int i = 0;
        while (i < n) {
            if (c[i] < i) {
                int j = i % 2 == 0 ? 0 : c[i];
                int t = p[j]; p[j] = p[i]; p[i] = t;
                best = Math.min(best, cost.total(p));
                c[i]++;
                i = 0;
            } else {
                c[i++] = 0;
            }
        }
        return best;
    }

    @Test
    void withoutCollisionsTheDynamicProgramIsExact() {
        Random rnd = new Random(1);
        SupportWeights noCollisions = new SupportWeights(1, 0);
        for (int n = 1; n <= 8; n++) {
            for (int trial = 0; trial < (n <= 6 ? 30 : 5); trial++) {
                SupportCost cost = instance(rnd, n, noCollisions);
                SupportMapping m = new DynamicProgrammingSupportMapper().map(cost);
                assertEquals(bruteForce(cost), m.cost(), 1e-9, "n=" + n + " trial " + trial);
                assertEquals(cost.total(m.positionOf()), m.cost(), 1e-9, "reported cost is the mapping's cost");
                assertIsPermutation(m.positionOf());
            }
        }
    }

    @Test
    void evaluatesExactlyNTimesTwoToTheNMinusOneMappings() {
        Random rnd = new Random(2);
        assertEquals(1024, new DynamicProgrammingSupportMapper().map(instance(rnd, 8, SupportWeights.THESIS)).evaluated());
        assertEquals(5120, new DynamicProgrammingSupportMapper().map(instance(rnd, 10, SupportWeights.THESIS)).evaluated());
        for (int n = 1; n <= 10; n++)
            assertEquals((long) n << (n - 1), new DynamicProgrammingSupportMapper().map(instance(rnd, n, SupportWeights.THESIS)).evaluated());
        assertEquals(0, new DynamicProgrammingSupportMapper().map(instance(rnd, 0, SupportWeights.THESIS)).evaluated());
    }

    @Test
    void withCollisionsTheDynamicProgramIsNeverBetterThanTheOptimumAndItsCostIsTrue() {
        Random rnd = new Random(3);
        for (int trial = 0; trial < 40; trial++) {
            SupportCost cost = instance(rnd, 6, SupportWeights.THESIS);
            SupportMapping dp = new DynamicProgrammingSupportMapper().map(cost);
            double optimum = bruteForce(cost);
            assertEquals(cost.total(dp.positionOf()), dp.cost(), 1e-9);
            assertTrue(dp.cost() >= optimum - 1e-9);
        }
    }

    @Test
    void exhaustiveMapperFindsTheBruteForceOptimumWithCollisions() {
        Random rnd = new Random(4);
        for (int n = 0; n <= 7; n++) {
            SupportCost cost = instance(rnd, n, SupportWeights.THESIS);
            SupportMapping m = new ExhaustiveSupportMapper().map(cost);
            assertEquals(n == 0 ? 0 : bruteForce(cost), m.cost(), 1e-9, "n=" + n);
            assertEquals(cost.total(m.positionOf()), m.cost(), 1e-9);
            assertIsPermutation(m.positionOf());
        }
    }

    @Test
    void crossingCountsForBothSupportPlayersAndOnceAgainstAnActiveRoute() {
        // Two support players whose routes cross midway (an X), and one active route that crosses the first one.
        List<Vector2> agents = List.of(new Vector2(-1, -1), new Vector2(-1, 1));
        List<Vector2> positions = List.of(new Vector2(1, 1), new Vector2(1, -1));
        SupportCost cost = new SupportCost(agents, positions, List.of(new Vector2(0.5, -3)), List.of(new Vector2(0.5, 3)),
                SupportWeights.THESIS, C);
        double d = Math.hypot(2, 2);
        // Player 0 → (1,1) crosses player 1 → (1,-1) at (0,0), 1.41 m from both starts: 100 for each player.
        // Player 0's route meets the active route at (0.5,0.5): 2.12 m vs 3.5 m, |Δ| < 1.5: 100. Player 1's
        // route meets it at (0.5,-0.5): 2.12 vs 2.5: 100.
        assertEquals(2 * d + 2 * 100 + 100 + 100, cost.total(new int[]{0, 1}), 1e-9);
        // The straight mapping crosses nothing between support players; both routes still cross the active one.
        // Player 0 → (1,-1) meets it at (0.5,-1): 1.5 m vs 2 m, 100; player 1 → (1,1) at (0.5,1): 1.5 vs 4 m, 2.
        assertEquals(2 + 2 + 100 + 2, cost.total(new int[]{1, 0}), 1e-9);
        assertArrayEquals(new int[]{1, 0}, new DynamicProgrammingSupportMapper().map(cost).positionOf());
    }

    @Test
    void scramMinimisesTheLongestDistanceThenTheSumOfSquares() {
        Random rnd = new Random(6);
        for (int n = 1; n <= 7; n++) {
            for (int trial = 0; trial < 10; trial++) {
                SupportCost cost = instance(rnd, n, SupportWeights.THESIS);
                int[] m = new ScramSupportMapper().map(cost).positionOf();
                assertIsPermutation(m);
                double[] best = bestMaxThenSquares(cost);
                assertEquals(best[0], longest(cost, m), 1e-9, "longest distance, n=" + n);
                assertEquals(best[1], squares(cost, m), 1e-6, "sum of squares, n=" + n);
            }
        }
    }

    @Test
    void sizesMustAgree() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SupportCost(
                List.of(Vector2.ZERO), List.of(), List.of(), List.of(), SupportWeights.THESIS, C));
        assertEquals("1 support players but 0 positions", e.getMessage());
    }

    static double longest(SupportCost c, int[] m) {
        double l = 0;
        for (int a = 0; a < m.length; a++) l = Math.max(l, c.distance(a, m[a]));
        return l;
    }

    static double squares(SupportCost c, int[] m) {
        double s = 0;
        for (int a = 0; a < m.length; a++) s += c.distance(a, m[a]) * c.distance(a, m[a]);
        return s;
    }

    /** {min over permutations of the longest distance, min sum of squares among those}. */
    private static double[] bestMaxThenSquares(SupportCost cost) {
        double[] best = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        permute(cost, new int[cost.size()], new boolean[cost.size()], 0, best);
        return best;
    }

    private static void permute(SupportCost cost, int[] p, boolean[] used, int i, double[] best) {
        if (i == p.length) {
            double l = longest(cost, p), s = squares(cost, p);
            if (l < best[0] - 1e-12 || (Math.abs(l - best[0]) <= 1e-12 && s < best[1])) { best[0] = l; best[1] = s; }
            return;
        }
        for (int q = 0; q < p.length; q++) {
            if (used[q]) continue;
            used[q] = true; p[i] = q;
            permute(cost, p, used, i + 1, best);
            used[q] = false;
        }
    }

    static void assertIsPermutation(int[] p) {
        boolean[] seen = new boolean[p.length];
        for (int x : p) { assertFalse(seen[x], "position " + x + " given twice"); seen[x] = true; }
    }
}

package phalanx.bench.search;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The CMA-ES search (issue 21) on synthetic objectives: no server. */
class CmaesSearchTest {

    static final double[] OPT = {3.0, -2.0, 1.5, 4.0};

    static CmaesSearch.Space sphereSpace() {
        return new CmaesSearch.Space(List.of("a", "b", "c", "d"), new double[] {0, 0, 0, 0}, new double[] {1, 1, 0.5, 2},
                new double[] {-10, -10, -10, -10}, new double[] {10, 10, 10, 10});
    }

    /** A shifted sphere, maximised: -(sum (p - OPT)^2); counts its calls. */
    static CmaesSearch.Evaluator sphere(AtomicInteger calls, int failAfter) {
        return (batch, done) -> {
            for (int i = 0; i < batch.size(); i++) {
                if (failAfter >= 0 && calls.get() >= failAfter) throw new IOException("killed");
                calls.incrementAndGet();
                Map<String, Double> p = batch.get(i);
                double s = 0;
                String[] k = {"a", "b", "c", "d"};
                for (int j = 0; j < 4; j++) s += Math.pow(p.get(k[j]) - OPT[j], 2);
                done.accept(i, -s, "");
            }
        };
    }

    @Test
    void convergesOnAShiftedSphere() throws Exception {
        CmaesSearch s = new CmaesSearch(sphereSpace(), new CmaesSearch.Settings(1.0, 0, 7, 120, 100000), Map.of(), null);
        CmaesSearch.Result r = s.run(sphere(new AtomicInteger(), -1), null);
        CmaesSearch.Eval b = r.best();
        String[] k = {"a", "b", "c", "d"};
        for (int j = 0; j < 4; j++)
            assertEquals(OPT[j], b.params().get(k[j]), 0.01, k[j] + " of the best " + b.params());
        assertTrue(b.score() > -1e-4, "best score " + b.score());
        // one batch per generation: the start point goes with generation 1, then lambda per generation
        assertEquals(r.evaluated(), s.evaluations().size());
    }

    /**
     * The batched passes evaluate exactly the points the library's own closed-loop run evaluates, one at a
     * time with the true values: the batching changes nothing about the search.
     */
    @Test
    void batchingEvaluatesExactlyWhatTheLibrarysOwnRunEvaluates() throws Exception {
        CmaesSearch.Settings set = new CmaesSearch.Settings(1.0, 0, 13, 30, 100000);
        CmaesSearch s = new CmaesSearch(sphereSpace(), set, Map.of(), null);
        s.run(sphere(new AtomicInteger(), -1), null);

        double[] step = {1, 1, 0.5, 2};
        java.util.List<String> direct = new java.util.ArrayList<>();
        org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer opt =
                new org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer(30, 0.0, true, 0, 0,
                        new org.apache.commons.math3.random.MersenneTwister(13L), false, null);
        double[] lo = new double[4], hi = new double[4], sig = new double[4];
        for (int j = 0; j < 4; j++) { lo[j] = -10 / step[j]; hi[j] = 10 / step[j]; sig[j] = 1.0; }
        opt.optimize(new org.apache.commons.math3.optim.MaxEval(100000),
                new org.apache.commons.math3.optim.nonlinear.scalar.ObjectiveFunction(x -> {
                    direct.add(java.util.Arrays.toString(x));
                    double v = 0;
                    for (int j = 0; j < 4; j++) v += Math.pow(x[j] * step[j] - OPT[j], 2);
                    return -v;
                }),
                org.apache.commons.math3.optim.nonlinear.scalar.GoalType.MAXIMIZE,
                new org.apache.commons.math3.optim.InitialGuess(new double[4]), new org.apache.commons.math3.optim.SimpleBounds(lo, hi),
                new org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer.Sigma(sig),
                new org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer.PopulationSize(s.lambda()));
        java.util.List<String> batched = s.evaluations().stream().map(e -> java.util.Arrays.toString(e.x())).toList();
        assertEquals(new java.util.ArrayList<>(new java.util.LinkedHashSet<>(direct)), batched);
        assertTrue(batched.size() > 100, batched.size() + " evaluations");
    }

    @Test
    void optimumOutsideTheLimitsEndsOnTheBound() throws Exception {
        CmaesSearch.Space box = new CmaesSearch.Space(List.of("a", "b", "c", "d"), new double[] {0, 0, 0, 0}, new double[] {1, 1, 0.5, 2},
                new double[] {-10, -10, -10, -10}, new double[] {10, 10, 1.0, 10});   // c's optimum 1.5 is out of the box
        CmaesSearch.Result r = new CmaesSearch(box, new CmaesSearch.Settings(1.0, 0, 3, 120, 100000), Map.of(), null)
                .run(sphere(new AtomicInteger(), -1), null);
        assertEquals(1.0, r.best().params().get("c"), 0.01);
        assertEquals(4.0, r.best().params().get("d"), 0.01);
    }

    @Test
    void aKilledAndRestartedSearchEndsWithTheSameBestAsAnUninterruptedOne(@TempDir Path dir) throws Exception {
        CmaesSearch.Settings set = new CmaesSearch.Settings(1.0, 0, 11, 25, 100000);
        AtomicInteger whole = new AtomicInteger();
        CmaesSearch.Result full = new CmaesSearch(sphereSpace(), set, Map.of(), dir.resolve("full.jsonl")).run(sphere(whole, -1), null);

        Path log = dir.resolve("killed.jsonl");
        AtomicInteger first = new AtomicInteger();
        // killed in the middle of a generation (37 is not a boundary: batches of lambda 8 + the start point, then 8)
        assertThrows(IOException.class, () -> new CmaesSearch(sphereSpace(), set, Map.of(), log).run(sphere(first, 37), null));
        assertEquals(37, first.get());
        // and the kill cut the last line in half
        Files.writeString(log, "{\"gen\":5,\"x\":[1.0,", StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);

        AtomicInteger second = new AtomicInteger();
        CmaesSearch restarted = new CmaesSearch(sphereSpace(), set, Map.of(), log);
        assertEquals(37, restarted.evaluations().size(), "the logged evaluations are read back, the cut line dropped");
        CmaesSearch.Result r = restarted.run(sphere(second, -1), null);

        assertEquals(whole.get(), first.get() + second.get(), "nothing logged is evaluated again");
        assertEquals(37, r.replayed());
        assertEquals(full.best().score(), r.best().score(), 0.0);
        assertArrayEquals(full.best().x(), r.best().x(), 0.0);
        assertEquals(Files.readAllLines(dir.resolve("full.jsonl")).size(), Files.readAllLines(log).size());

        // a finished search run again only replays
        AtomicInteger third = new AtomicInteger();
        CmaesSearch.Result again = new CmaesSearch(sphereSpace(), set, Map.of(), log).run(sphere(third, -1), null);
        assertEquals(0, third.get());
        assertArrayEquals(full.best().x(), again.best().x(), 0.0);

        // and a bigger generation budget continues it
        CmaesSearch.Result longer = new CmaesSearch(sphereSpace(), new CmaesSearch.Settings(1.0, 0, 11, 40, 100000), Map.of(), log)
                .run(sphere(third, -1), null);
        assertTrue(third.get() > 0 && longer.best().score() >= full.best().score());
    }

    @Test
    void aLogOfAnotherSearchIsRefused(@TempDir Path dir) throws Exception {
        Path log = dir.resolve("l.jsonl");
        new CmaesSearch(sphereSpace(), new CmaesSearch.Settings(1.0, 0, 1, 2, 1000), Map.of(), log).run(sphere(new AtomicInteger(), -1), null);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new CmaesSearch(sphereSpace(), new CmaesSearch.Settings(1.0, 0, 2, 2, 1000), Map.of(), log));
        assertTrue(e.getMessage().contains("belongs to another search"), e.getMessage());
        Files.writeString(log, "not json\n");
        e = assertThrows(IllegalArgumentException.class,
                () -> new CmaesSearch(sphereSpace(), new CmaesSearch.Settings(1.0, 0, 2, 2, 1000), Map.of(), log));
        assertTrue(e.getMessage().contains("not a search header"), e.getMessage());
    }

    @Test
    void badSettingsAndSpacesAreRefusedWithTheirName() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new CmaesSearch.Settings(0, 0, 1, 10, 10))
                .getMessage().contains("--sigma"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new CmaesSearch.Settings(1, 1, 1, 10, 10))
                .getMessage().contains("--lambda"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new CmaesSearch.Settings(1, 0, 1, 0, 10))
                .getMessage().contains("--generations"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new CmaesSearch.Space(List.of("kk"), new double[] {0},
                new double[] {0}, new double[] {-1}, new double[] {1})).getMessage().contains("'kk': step"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new CmaesSearch.Space(List.of("kk"), new double[] {0},
                new double[] {1}, new double[] {1}, new double[] {-1})).getMessage().contains("'kk': limits"));
        assertNotNull(sphereSpace());
    }
}

package phalanx.bench.search;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.commons.math3.optim.InitialGuess;
import org.apache.commons.math3.optim.MaxEval;
import org.apache.commons.math3.optim.SimpleBounds;
import org.apache.commons.math3.optim.nonlinear.scalar.GoalType;
import org.apache.commons.math3.optim.nonlinear.scalar.ObjectiveFunction;
import org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer;
import org.apache.commons.math3.random.MersenneTwister;

/**
 * CMA-ES over a box of named parameters (the kick generator's, issue 21), on Apache Commons Math 3.6.1's
 * {@link CMAESOptimizer}, maximising a score, with every evaluation appended to a log it can resume from.
 *
 * <p><b>How a generation is evaluated in parallel.</b> CMAESOptimizer is closed-loop: its {@code doOptimize}
 * calls the objective once per candidate, one after another, and has no ask/tell interface. But within a
 * generation the lambda candidates are all drawn before any of their values is used (the normal samples of
 * the whole generation are drawn at its start; a feasibility resample depends only on the bounds, and this
 * search never resamples: checkFeasableCount 0, out-of-box points are repaired and penalised). So the
 * optimizer is driven in <em>passes</em>, each a fresh CMAESOptimizer with a fresh MersenneTwister of the same
 * seed: the objective answers from a cache of evaluated points; the first point it does not know opens a
 * pending batch and gets a placeholder value (0), as do the rest of that generation's new points; the
 * first call of the next generation aborts the pass (an exception out of {@code optimize}). The batch, the
 * whole generation, is then evaluated together ({@link Evaluator#evaluate}, N at a time for the command
 * evaluator), cached and logged, and the next pass replays every cached value exactly (same seed, same
 * arithmetic) up to the next unknown generation. The start point (iteration 0) is batched with generation 1,
 * whose samples do not depend on it. Placeholder values never survive: a pass that ends (the optimizer stops
 * on its own) with a pending batch is evaluated and run again. Costs and limits: a pass replays all earlier
 * generations (matrix work only, milliseconds against seconds-long bench runs); the parallelism is at most
 * lambda (plus 1 in the first batch) candidates, and the generation is a barrier (the slowest candidate
 * holds the next generation back). The method relies on 3.6.1's sampling order; the tests check that the
 * result does not depend on the number of jobs or on a restart.
 *
 * <p><b>Coordinates.</b> Each parameter is searched in units of its step (x = value / step), so one sigma is
 * one step of the (1+1) search on every axis; bounds are the parameter limits in the same units.
 *
 * <p><b>Log.</b> JSON lines: a header (the search's definition: keys, start, steps, limits, sigma, lambda,
 * seed) then one line per evaluation: generation, the optimizer's point x, the parameters, the score and the
 * evaluator's detail. A restart with the same definition reads it, caches every logged point and so
 * continues where it stopped (a last line cut by a kill is dropped); a log of another definition is
 * refused. The generation and evaluation budgets may differ between runs (a finished search can be extended).
 */
public final class CmaesSearch {

    /** Scores a batch of candidates (the parameter maps, each with every key); higher is better. */
    public interface Evaluator {
        /** Evaluates every candidate; {@code done} is told of each result as soon as it is known. */
        void evaluate(List<Map<String, Double>> batch, ResultSink done) throws IOException, InterruptedException;
    }

    /** Receives one evaluated candidate (thread-safe use is the evaluator's duty: calls are synchronized here). */
    public interface ResultSink {
        void accept(int index, double score, String detail);
    }

    /** The searched box: keys, the start, the step (one sigma) and the limits of each. */
    public record Space(List<String> keys, double[] start, double[] step, double[] lo, double[] hi) {
        public Space {
            int n = keys.size();
            if (n == 0) throw new IllegalArgumentException("the search needs at least one parameter key");
            if (start.length != n || step.length != n || lo.length != n || hi.length != n)
                throw new IllegalArgumentException("keys, start, step and limits must have the same length");
            for (int i = 0; i < n; i++) {
                String k = keys.get(i);
                if (!(step[i] > 0)) throw new IllegalArgumentException("parameter '" + k + "': step must be > 0, got " + step[i]);
                if (!(lo[i] < hi[i])) throw new IllegalArgumentException("parameter '" + k + "': limits [" + lo[i] + ", " + hi[i] + "] are empty");
            }
        }
    }

    /** The search's settings; generations and maxEvals are budgets, the rest define the search (the log header). */
    public record Settings(double sigma, int lambda, long seed, int generations, int maxEvals) {
        public Settings {
            if (!(sigma > 0)) throw new IllegalArgumentException("--sigma must be > 0 (in steps), got " + sigma);
            if (lambda < 0 || lambda == 1) throw new IllegalArgumentException("--lambda must be at least 2 (0 = CMA-ES's default), got " + lambda);
            if (generations < 1) throw new IllegalArgumentException("--generations must be at least 1, got " + generations);
            if (maxEvals < 1) throw new IllegalArgumentException("--max-evals must be at least 1, got " + maxEvals);
        }
    }

    /** One evaluation: optimizer point, parameters, score. */
    public record Eval(int generation, double[] x, Map<String, Double> params, double score, String detail) {}

    /** What a search returns: its best evaluation, how many were run now and how many were read from the log. */
    public record Result(Eval best, int evaluated, int replayed, int generations, boolean stoppedByBudget) {}

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Space space;
    private final Settings settings;
    private final Map<String, Object> fixed;
    private final Path log;
    private final int lambda;
    private final Map<String, Eval> cache = new HashMap<>();
    private final List<Eval> order = new ArrayList<>();
    private int replayed;

    /**
     * @param fixed parameters passed to every candidate unchanged (the generator's other keys); may be empty
     * @param log the evaluation log (created, or resumed when it exists); null = no log
     */
    public CmaesSearch(Space space, Settings settings, Map<String, Object> fixed, Path log) throws IOException {
        this.space = space;
        this.settings = settings;
        this.fixed = new LinkedHashMap<>(fixed);
        this.log = log;
        int n = space.keys().size();
        this.lambda = settings.lambda() > 0 ? settings.lambda() : 4 + (int) (3 * Math.log(n));
        if (log != null) openLog();
    }

    public int lambda() { return lambda; }

    double[] lower() { double[] l = new double[space.lo().length]; for (int i = 0; i < l.length; i++) l[i] = space.lo()[i] / space.step()[i]; return l; }
    double[] upper() { double[] u = new double[space.hi().length]; for (int i = 0; i < u.length; i++) u[i] = space.hi()[i] / space.step()[i]; return u; }

    /** The parameters (every key) of an optimizer point. */
    Map<String, Double> decode(double[] x) {
        Map<String, Double> p = new LinkedHashMap<>();
        for (int i = 0; i < x.length; i++) p.put(space.keys().get(i), x[i] * space.step()[i]);
        return p;
    }

    private static String key(double[] x) { return Arrays.toString(x); }

    /** Thrown out of the objective to end a pass at the first call of the generation after the pending one. */
    private static final class PassDone extends RuntimeException {
        private static final long serialVersionUID = 1L;
        PassDone() { super(null, null, false, false); }
    }

    /** Runs (or resumes) the search; {@code progress} gets a line per evaluation (may be null). */
    public Result run(Evaluator evaluator, java.util.function.Consumer<String> progress) throws IOException, InterruptedException {
        int n = space.keys().size();
        double[] lo = lower(), hi = upper();
        double[] x0 = new double[n], sig = new double[n];
        for (int i = 0; i < n; i++) {
            x0[i] = Math.min(hi[i], Math.max(lo[i], space.start()[i] / space.step()[i]));
            sig[i] = Math.min(settings.sigma(), hi[i] - lo[i]);
        }
        int evaluatedNow = 0;
        int lastGeneration = 0;
        boolean budget;
        while (true) {
            CMAESOptimizer opt = new CMAESOptimizer(settings.generations(), 0.0, true, 0, 0,
                    new MersenneTwister(settings.seed()), false, null);
            List<double[]> pending = new ArrayList<>();
            List<Integer> pendingGen = new ArrayList<>();
            java.util.Set<String> pendingKeys = new java.util.HashSet<>();
            int[] batchGen = {-1};
            ObjectiveFunction f = new ObjectiveFunction(x -> {
                Eval e = cache.get(key(x));
                int g = opt.getIterations();
                if (e != null) return e.score();
                int batch = Math.max(1, g);   // the start point (iteration 0) goes with generation 1
                if (batchGen[0] < 0) batchGen[0] = batch;
                if (batch != batchGen[0]) throw new PassDone();
                if (pendingKeys.add(key(x))) { pending.add(x.clone()); pendingGen.add(g); }
                return 0.0;
            });
            boolean finished = false;
            try {
                opt.optimize(new MaxEval(settings.maxEvals()), f, GoalType.MAXIMIZE, new InitialGuess(x0),
                        new SimpleBounds(lo, hi), new CMAESOptimizer.Sigma(sig), new CMAESOptimizer.PopulationSize(lambda));
                finished = true;
            } catch (PassDone e) {
                // the pending generation is complete
            } catch (org.apache.commons.math3.exception.TooManyEvaluationsException e) {
                finished = true;
            }
            lastGeneration = opt.getIterations();
            if (pending.isEmpty()) {
                budget = finished;
                break;
            }
            List<Map<String, Double>> batch = new ArrayList<>();
            for (double[] x : pending) batch.add(withFixed(decode(x)));
            Eval[] got = new Eval[pending.size()];
            evaluator.evaluate(batch, (i, score, detail) -> {
                synchronized (this) {
                    Eval e = new Eval(pendingGen.get(i), pending.get(i), decode(pending.get(i)), score, detail == null ? "" : detail);
                    got[i] = e;
                    record(e);
                    if (progress != null) progress.accept(describe(e));
                }
            });
            for (int i = 0; i < got.length; i++)
                if (got[i] == null) throw new IOException("the evaluator returned no score for candidate " + i + " of generation " + pendingGen.get(i));
            evaluatedNow += got.length;
        }
        return new Result(best(), evaluatedNow, replayed, lastGeneration, budget);
    }

    private Map<String, Double> withFixed(Map<String, Double> p) {
        Map<String, Double> all = new LinkedHashMap<>();
        for (Map.Entry<String, Object> e : fixed.entrySet())
            if (e.getValue() instanceof Number num) all.put(e.getKey(), num.doubleValue());
        all.putAll(p);
        return all;
    }

    /** The best evaluation so far (the earliest of equal scores), or null before any. */
    public synchronized Eval best() {
        Eval b = null;
        for (Eval e : order) if (b == null || e.score() > b.score()) b = e;
        return b;
    }

    public synchronized List<Eval> evaluations() { return List.copyOf(order); }

    String describe(Eval e) {
        Eval b = best();
        return "gen " + e.generation() + " eval " + order.size() + " score " + fmt(e.score()) + " best " + fmt(b.score())
                + " " + json(e.params()) + (e.detail().isEmpty() ? "" : " " + e.detail());
    }

    private static String fmt(double v) { return String.format(java.util.Locale.ROOT, "%.4f", v); }

    private static String json(Object o) {
        try { return JSON.writeValueAsString(o); } catch (IOException e) { throw new UncheckedIOException(e); }
    }

    // ---- the log ----

    private ObjectNode header() {
        ObjectNode h = JSON.createObjectNode();
        h.put("search", "cmaes");
        ArrayNode k = h.putArray("keys"); space.keys().forEach(k::add);
        array(h, "start", space.start()); array(h, "step", space.step()); array(h, "lo", space.lo()); array(h, "hi", space.hi());
        h.put("sigma", settings.sigma()); h.put("lambda", lambda); h.put("seed", settings.seed());
        return h;
    }

    private static void array(ObjectNode o, String name, double[] v) { ArrayNode a = o.putArray(name); for (double d : v) a.add(d); }

    private void openLog() throws IOException {
        ObjectNode want = header();
        if (!Files.exists(log) || Files.size(log) == 0) {
            if (log.getParent() != null) Files.createDirectories(log.getParent());
            Files.writeString(log, JSON.writeValueAsString(want) + "\n", StandardCharsets.UTF_8);
            return;
        }
        byte[] bytes = Files.readAllBytes(log);
        String text = new String(bytes, StandardCharsets.UTF_8);
        int end = text.lastIndexOf('\n') + 1;   // a last line without its newline was cut by a kill
        if (end < text.length()) {
            System.err.println("cmaes: dropping the unfinished last line of " + log + " (the search was killed while writing it)");
            try (RandomAccessFile raf = new RandomAccessFile(log.toFile(), "rw")) {
                raf.setLength(text.substring(0, end).getBytes(StandardCharsets.UTF_8).length);
            }
            text = text.substring(0, end);
        }
        String[] lines = text.split("\n");
        JsonNode got;
        try {
            got = JSON.readTree(lines[0]);
        } catch (IOException e) {
            throw new IllegalArgumentException("log " + log + ": the first line is not a search header (" + e.getMessage() + ")");
        }
        if (!JSON.readTree(JSON.writeValueAsString(want)).equals(got))   // as read back: numbers' node types alike
            throw new IllegalArgumentException("log " + log + " belongs to another search (its header " + lines[0]
                    + " differs from this one's " + want + "): use another --log, or the same keys, start, sigma, lambda and seed");
        for (int i = 1; i < lines.length; i++) {
            if (lines[i].isBlank()) continue;
            try {
                JsonNode e = JSON.readTree(lines[i]);
                double[] x = new double[e.get("x").size()];
                for (int j = 0; j < x.length; j++) x[j] = e.get("x").get(j).doubleValue();
                if (x.length != space.keys().size()) throw new IOException("point of " + x.length + " coordinates");
                Eval ev = new Eval(e.get("gen").intValue(), x, decode(x), e.get("score").doubleValue(),
                        e.has("detail") ? e.get("detail").asText() : "");
                if (cache.putIfAbsent(key(x), ev) == null) order.add(ev);
                replayed++;
            } catch (IOException | RuntimeException ex) {
                throw new IllegalArgumentException("log " + log + " line " + (i + 1) + " is not an evaluation: " + ex.getMessage());
            }
        }
    }

    private void record(Eval e) {
        if (cache.putIfAbsent(key(e.x()), e) == null) order.add(e);
        if (log == null) return;
        ObjectNode o = JSON.createObjectNode();
        o.put("gen", e.generation());
        array(o, "x", e.x());
        ObjectNode p = o.putObject("params");
        e.params().forEach(p::put);
        o.put("score", e.score());
        o.put("detail", e.detail());
        try {
            Files.writeString(log, JSON.writeValueAsString(o) + "\n", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        } catch (IOException ex) {
            throw new UncheckedIOException(ex);
        }
    }
}

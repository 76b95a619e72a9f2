package phalanx.bench.search;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import phalanx.match.ParallelHosts;

/**
 * Command line of the CMA-ES search (issue 21); {@code scripts/phalanx bench kick-search cmaes} builds the
 * space file and the evaluator command and runs this. Usage: see {@link #USAGE}. Exit status 2 on a bad
 * argument, 1 when an evaluation fails (the log keeps what was done: run the same command again to resume).
 */
public final class CmaesMain {

    static final String USAGE = String.join("\n",
            "usage: CmaesMain --space SPACE.json --eval 'COMMAND {params}' [options]",
            "  --space FILE        {\"start\": {every parameter}, \"keys\": [searched], \"step\": {key: step}, \"limits\": {key: [lo, hi]}}",
            "  --eval CMD          shell command scoring one candidate: {params} = its JSON file; prints 'SCORE <number>'",
            "                      (higher is better); SEARCH_SLOT = its job slot 0..jobs-1 in the environment",
            "  --jobs N            evaluations at a time (1); with --hosts, on each host without N/",
            "  --log FILE          evaluation log (JSON lines); an existing one is resumed (none)",
            "  --seed N            random seed (1)",
            "  --generations N     generation budget (30)",
            "  --max-evals N       evaluation budget, replayed ones included (100000)",
            "  --lambda N          candidates per generation (0 = 4 + 3 ln(dimension))",
            "  --sigma S           initial step size in units of each parameter's step (1)",
            "  --timeout S         seconds one evaluation may take (900)",
            "  --best FILE         the best candidate's parameters (every key), as JSON",
            "  --work DIR          the candidates' files (a temporary folder)",
            "  --parallel          run each generation's candidates through GNU parallel (-j N, here) instead of threads",
            "  --hosts FILE        ... on other machines: parallel's --sshloginfile, one [N/][user@]host a line (N jobs there,",
            "                      else --jobs), ':' for this one; the command runs from each host's checkout, SEARCH_SLOT",
            "                      0..N-1 per host; a candidate that fails on a host is tried on another (WORK/failures.log)",
            "  --retries N         with --hosts: tries per candidate, each on another host when there is one (3)",
            "  --ssh CMD           with --hosts: the ssh command (ssh)",
            "  --remote-dir D      with --hosts: the checkout on the hosts (this checkout's path; relative: from the home)");

    private CmaesMain() {}

    public static void main(String[] args) {
        try {
            System.exit(run(args));
        } catch (IllegalArgumentException e) {
            System.err.println("cmaes: " + e.getMessage());
            System.exit(2);
        }
    }

    /** Parses the arguments and runs the search; throws IllegalArgumentException on a bad argument. */
    static int run(String[] args) {
        Map<String, String> o = parse(args);
        if (o.containsKey("help")) { System.out.println(USAGE); return 0; }
        String spaceFile = require(o, "space"), eval = require(o, "eval");
        int jobs = integer(o, "jobs", 1), generations = integer(o, "generations", 30), maxEvals = integer(o, "max-evals", 100000),
                lambda = integer(o, "lambda", 0);
        long seed = longValue(o, "seed", 1), timeout = longValue(o, "timeout", 900);
        double sigma = number(o, "sigma", 1.0);
        try {
            CommandEvaluator.Hosts hosts = hosts(o);
            Path work = o.containsKey("work") ? Path.of(o.get("work")) : Files.createTempDirectory("cmaes-");
            CommandEvaluator evaluator = new CommandEvaluator(eval, jobs, timeout, work, o.containsKey("parallel"), hosts);
            Map<String, Object> start = new LinkedHashMap<>();
            CmaesSearch.Space space = readSpace(Path.of(spaceFile), start);
            CmaesSearch.Settings settings = new CmaesSearch.Settings(sigma, lambda, seed, generations, maxEvals);
            CmaesSearch search = new CmaesSearch(space, settings, start, o.containsKey("log") ? Path.of(o.get("log")) : null);
            System.out.println("cmaes: " + space.keys().size() + " parameters " + space.keys() + ", lambda " + search.lambda()
                    + ", seed " + seed + ", " + jobs + " job(s)" + (hosts != null ? " on each host without N/ of " + o.get("hosts") + ", through GNU parallel"
                    : o.containsKey("parallel") ? " through GNU parallel" : "") + (o.containsKey("log") ? ", log " + o.get("log") : ""));
            if (!search.evaluations().isEmpty())
                System.out.println("cmaes: resuming from " + search.evaluations().size() + " logged evaluations");
            CmaesSearch.Result r;
            long t0 = System.nanoTime();
            try {
                r = search.run(evaluator, line -> System.out.println(line));
            } catch (IOException e) {
                System.err.println("cmaes: " + e.getMessage());
                System.err.println("cmaes: stopped; the finished evaluations are in the log: the same command resumes the search");
                return 1;
            }
            double hours = (System.nanoTime() - t0) / 3.6e12;
            Map<String, Object> best = new LinkedHashMap<>(start);
            best.putAll(r.best().params());
            String bestJson = new ObjectMapper().writeValueAsString(best);
            System.out.printf(java.util.Locale.ROOT, "cmaes: %d generations, %d evaluations run now (%.1f per hour), %d read from the log%n",
                    r.generations(), r.evaluated(), r.evaluated() / Math.max(hours, 1e-9), r.replayed());
            System.out.println("BEST " + r.best().score() + " " + bestJson);
            if (o.containsKey("best"))
                new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValue(Path.of(o.get("best")).toFile(), best);
            return 0;
        } catch (IOException e) {
            throw new IllegalArgumentException(e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }

    private static final List<String> FLAGS = List.of("space", "eval", "jobs", "log", "seed", "generations", "max-evals",
            "lambda", "sigma", "timeout", "best", "work", "hosts", "retries", "ssh", "remote-dir");

    /** The --hosts options, or null without --hosts (then its companions are refused). */
    private static CommandEvaluator.Hosts hosts(Map<String, String> o) {
        if (!o.containsKey("hosts")) {
            for (String k : List.of("retries", "ssh", "remote-dir"))
                if (o.containsKey(k)) throw new IllegalArgumentException("--" + k + " needs --hosts");
            return null;
        }
        CommandEvaluator.Hosts h = new CommandEvaluator.Hosts(Path.of(o.get("hosts")), o.get("ssh"), o.get("remote-dir"), integer(o, "retries", 3));
        if (!ParallelHosts.available())
            throw new IllegalArgumentException("--hosts needs GNU parallel (Debian package parallel; scripts/setup.sh installs it)");
        return h;
    }

    static Map<String, String> parse(String[] args) {
        Map<String, String> o = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--help") || a.equals("-h")) { o.put("help", ""); continue; }
            if (a.equals("--parallel")) { o.put("parallel", ""); continue; }
            if (!a.startsWith("--") || !FLAGS.contains(a.substring(2)))
                throw new IllegalArgumentException("unknown argument '" + a + "'\n" + USAGE);
            if (i + 1 >= args.length) throw new IllegalArgumentException(a + " needs a value");
            o.put(a.substring(2), args[++i]);
        }
        return o;
    }

    private static String require(Map<String, String> o, String k) {
        String v = o.get(k);
        if (v == null) throw new IllegalArgumentException("--" + k + " is required\n" + USAGE);
        return v;
    }

    private static int integer(Map<String, String> o, String k, int d) {
        try { return o.containsKey(k) ? Integer.parseInt(o.get(k)) : d; }
        catch (NumberFormatException e) { throw new IllegalArgumentException("--" + k + " must be a whole number, got '" + o.get(k) + "'"); }
    }

    private static long longValue(Map<String, String> o, String k, long d) {
        try { return o.containsKey(k) ? Long.parseLong(o.get(k)) : d; }
        catch (NumberFormatException e) { throw new IllegalArgumentException("--" + k + " must be a whole number, got '" + o.get(k) + "'"); }
    }

    private static double number(Map<String, String> o, String k, double d) {
        try { return o.containsKey(k) ? Double.parseDouble(o.get(k)) : d; }
        catch (NumberFormatException e) { throw new IllegalArgumentException("--" + k + " must be a number, got '" + o.get(k) + "'"); }
    }

    /** Reads the space file; {@code startOut} gets every start parameter (searched or not). */
    static CmaesSearch.Space readSpace(Path file, Map<String, Object> startOut) throws IOException {
        if (!Files.exists(file)) throw new IllegalArgumentException("--space " + file + ": no such file");
        JsonNode s;
        try {
            s = new ObjectMapper().readTree(file.toFile());
        } catch (IOException e) {
            throw new IllegalArgumentException("--space " + file + " is not JSON: " + e.getMessage());
        }
        for (String f : List.of("start", "keys", "step", "limits"))
            if (!s.has(f)) throw new IllegalArgumentException("--space " + file + " has no \"" + f + "\"");
        for (Iterator<Map.Entry<String, JsonNode>> it = s.get("start").fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            startOut.put(e.getKey(), e.getValue().isNumber() ? (Object) e.getValue().doubleValue() : e.getValue().asText());
        }
        List<String> keys = new ArrayList<>();
        s.get("keys").forEach(k -> keys.add(k.asText()));
        int n = keys.size();
        double[] start = new double[n], step = new double[n], lo = new double[n], hi = new double[n];
        for (int i = 0; i < n; i++) {
            String k = keys.get(i);
            if (keys.indexOf(k) != i) throw new IllegalArgumentException("parameter '" + k + "' is listed twice");
            JsonNode v = s.get("start").get(k), st = s.get("step").get(k), lim = s.get("limits").get(k);
            if (v == null || !v.isNumber()) throw new IllegalArgumentException("parameter '" + k + "' has no numeric start value");
            if (st == null || !st.isNumber()) throw new IllegalArgumentException("parameter '" + k + "' has no step");
            if (lim == null || lim.size() != 2) throw new IllegalArgumentException("parameter '" + k + "' has no limits [lo, hi]");
            start[i] = v.doubleValue(); step[i] = st.doubleValue(); lo[i] = lim.get(0).doubleValue(); hi[i] = lim.get(1).doubleValue();
        }
        return new CmaesSearch.Space(keys, start, step, lo, hi);
    }
}

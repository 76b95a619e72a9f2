package phalanx.bench.walk;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import phalanx.bench.search.CmaesMain;
import phalanx.motion.walk.WalkConfig;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * scripts/phalanx bench walk-search: the walk's CMA-ES search (issue 21) on the kick's machinery. It builds
 * the search space from {@link WalkConfig} (start = the type's config with the {@code --set} overrides,
 * steps from FIELDS as {@code bench walk --search} takes them, limits = WalkConfig's ranges) and the
 * evaluator command, one {@code WalkTrial --score} per candidate on port base + SEARCH_SLOT, and hands
 * both with the other flags to {@link CmaesMain}: optimizer, job slots, log and resume are CmaesMain's.
 * Exit status 2 on a bad argument.
 */
public final class WalkSearch {

    static final String USAGE = String.join("\n",
            "usage: scripts/phalanx bench walk-search space|cmaes FIELDS [--type 0] [--set field=value,...] [--search-seconds 15]",
            "           " + phalanx.match.Flags.SERVER_USAGE + " [cmaes: --jobs N] [--parallel] [--log walk-cmaes.jsonl] [--generations 30]",
            "           [--best FILE] [--seed 1] [--lambda 0] [--sigma 1] [--timeout 900] [--max-evals N] [--work DIR]",
            "  FIELDS      field:step,... searched (as bench walk --search takes them); one sigma = one step",
            "  space       prints the search space (start, keys, step, limits) as JSON",
            "  cmaes       runs the search: candidate j of a generation scored by 'bench walk --score' on",
            "              --port + slot and --monitor-port + slot (slot 0..jobs-1: a server each);",
            "              the same command again resumes from the log. WALK_CMAES_EVAL='COMMAND {params}'",
            "              replaces the scoring command (a dry run without a server)");

    /** The flags that shape the space and the trial; every other flag is CmaesMain's. */
    private static final Set<String> WALK_FLAGS = Set.of("--type", "--set", "--search-seconds", "--host", "--port", "--monitor-port");
    private static final String DEFAULT_LOG = "walk-cmaes.jsonl";

    private WalkSearch() {}

    public static void main(String[] args) {
        if (List.of(args).contains("--help") || List.of(args).contains("-h")) { System.out.println(USAGE); return; }
        try {
            if (args.length > 0 && args[0].equals("cmaes")) CmaesMain.main(cmaesArguments(args));   // exits with CmaesMain's status
            else System.out.println(space(args).toString());
        } catch (IllegalArgumentException e) {
            System.err.println("walk-search: " + e.getMessage());
            System.exit(2);
        }
    }

    /** {@code space FIELDS [walk flags]}: the space as CmaesMain reads it. */
    static ObjectNode space(String[] args) {
        Command c = parse(args, "space");
        if (!c.cmaesArgs.isEmpty()) throw new IllegalArgumentException("space takes only " + WALK_FLAGS + ", got '" + c.cmaesArgs.get(0) + "'\n" + USAGE);
        return c.space();
    }

    /**
     * {@code cmaes FIELDS [flags]}: writes the space beside the log ({@code LOG.space.json}) and returns
     * CmaesMain's arguments: the space, the evaluator command and the caller's other flags.
     */
    static String[] cmaesArguments(String[] args) {
        Command c = parse(args, "cmaes");
        List<String> out = new ArrayList<>(c.cmaesArgs);
        int logAt = out.indexOf("--log");
        if (logAt < 0) out.addAll(List.of("--log", DEFAULT_LOG));
        else if (logAt + 1 >= out.size()) throw new IllegalArgumentException("--log needs a value");
        Path spaceFile = Path.of(out.get(out.indexOf("--log") + 1) + ".space.json").toAbsolutePath();
        try {
            Files.writeString(spaceFile, c.space().toString());
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot write the space file " + spaceFile + ": " + e.getMessage());
        }
        String eval = System.getenv("WALK_CMAES_EVAL");
        if (eval == null) eval = c.evalCommand();
        System.out.printf(Locale.ROOT, "walk-search cmaes: type %d, %d fields, trials of %.0f s on ports %d+slot / %d+slot%n",
                c.type, c.steps.size(), c.trial.searchSeconds(), c.trial.port(), c.trial.monitorPort());
        out.addAll(0, List.of("--space", spaceFile.toString(), "--eval", eval));
        return out.toArray(String[]::new);
    }

    /** A parsed command line: the searched fields with their steps, the trial's options, CmaesMain's flags. */
    private record Command(Map<String, Double> steps, WalkTrialOptions trial, int type, List<String> cmaesArgs) {

        ObjectNode space() {
            ObjectMapper json = new ObjectMapper();
            ObjectNode s = json.createObjectNode();
            WalkConfig start = trial.config(type);
            ObjectNode st = s.putObject("start");
            for (String f : WalkConfig.FIELDS) st.put(f, start.get(f));
            steps.keySet().forEach(s.putArray("keys")::add);
            ObjectNode step = s.putObject("step"), limits = s.putObject("limits");
            steps.forEach((f, v) -> {
                step.put(f, v);
                double[] r = WalkConfig.range(f);
                limits.putArray(f).add(r[0]).add(r[1]);
            });
            return s;
        }

        /**
         * One WalkTrial --score with the candidate as --set pairs: its JSON file ({"f":v,...}, as
         * CommandEvaluator writes it) turned into f=v,... by tr. `java` from PATH, as run-java does. The
         * classpath is the one gradle wrote in the checkout the job runs in (on another host, its own checkout,
         * wherever --remote-dir put it), else this search's own.
         */
        String evalCommand() {
            String slot = "${SEARCH_SLOT:-0}";
            String cp = "\"$(cat bench/build/runtime-classpath.txt 2>/dev/null || echo " + quote(System.getProperty("java.class.path")) + ")\"";
            return String.join(" ", "java", "-cp", cp, WalkTrial.class.getName(), "--score",
                    "--type", Integer.toString(type), "--host", quote(trial.host()),
                    "--port", "$((" + trial.port() + " + " + slot + "))", "--monitor-port", "$((" + trial.monitorPort() + " + " + slot + "))",
                    "--search-seconds", Double.toString(trial.searchSeconds()),
                    "--set", "\"$(tr -d '{}\" \\n' < {params} | tr : =)\"");
        }
    }

    private static Command parse(String[] args, String mode) {
        if (args.length == 0 || !args[0].equals(mode)) throw new IllegalArgumentException("a mode is needed: space or cmaes\n" + USAGE);
        if (args.length < 2 || args[1].startsWith("-"))
            throw new IllegalArgumentException(mode + " needs FIELDS (field:step,...) first, e.g. stepSeconds:0.01,torsoLeanDeg:2\n" + USAGE);
        Map<String, Double> steps = WalkTrialOptions.steps("FIELDS", args[1]);
        List<String> walkArgs = new ArrayList<>(), cmaesArgs = new ArrayList<>();
        for (int i = 2; i < args.length; i++) {
            if (!WALK_FLAGS.contains(args[i])) { cmaesArgs.add(args[i]); continue; }
            if (i + 1 >= args.length) throw new IllegalArgumentException(args[i] + " needs a value");
            walkArgs.add(args[i]);
            walkArgs.add(args[++i]);
        }
        if (!walkArgs.contains("--type")) walkArgs.addAll(List.of("--type", "0"));
        WalkTrialOptions trial = WalkTrialOptions.parse(walkArgs.toArray(String[]::new));
        if (trial.types().size() != 1) throw new IllegalArgumentException("--type: the search tunes one robot type, got " + trial.types());
        trial.config(trial.types().get(0));   // a bad --set value is refused here, before anything runs
        return new Command(steps, trial, trial.types().get(0), cmaesArgs);
    }

    private static String quote(String s) { return "'" + s.replace("'", "'\\''") + "'"; }
}

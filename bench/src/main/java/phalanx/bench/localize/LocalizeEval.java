package phalanx.bench.localize;

import phalanx.comm.recording.GroundTruth;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.comm.recording.Recordings;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.belief.BeliefStats;
import phalanx.localization.belief.BeliefStore;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.robot.NaoModel;
import phalanx.model.field.Angles;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Replays recordings through the belief store and measures it against their ground truth
 * (scripts/phalanx bench localize). Every cycle with a belief counts: the self error compares the belief
 * (converted from the team's frame to the field frame) with the torso; cycles where the torso
 * leans more than 45° (a fall, S3) are reported apart and left out of the self figures.
 */
public final class LocalizeEval {
    private static final Pattern SCENE = Pattern.compile("\\(scene\\s+\\S*?nao(?:_hetero)?\\.rsg(?:\\s+(\\d+))?\\)");
    private static final Pattern TEAM = Pattern.compile("\\(teamname\\s+([^)\\s]+)\\)");

    /** The errors of one or more recordings. */
    public static final class Result {
        final String name;
        final List<Double> self = new ArrayList<>(), theta = new ArrayList<>(), ball = new ArrayList<>(),
                fallenSelf = new ArrayList<>();
        long cycles, malformed, fallenCycles, vision, fixes;
        final List<BeliefStats> stats = new ArrayList<>();

        Result(String name) { this.name = name; }

        void add(Result r) {
            self.addAll(r.self); theta.addAll(r.theta); ball.addAll(r.ball); fallenSelf.addAll(r.fallenSelf);
            cycles += r.cycles; malformed += r.malformed; fallenCycles += r.fallenCycles;
            vision += r.vision; fixes += r.fixes; stats.addAll(r.stats);
        }

        public double selfMedian() { return quantile(self, 0.5); }
        public double selfP95() { return quantile(self, 0.95); }
        public double selfMax() { return quantile(self, 1.0); }
        public double thetaMedian() { return quantile(theta, 0.5); }
        public double thetaP95() { return quantile(theta, 0.95); }
        public double ballMedian() { return quantile(ball, 0.5); }
        public double ballP95() { return quantile(ball, 0.95); }
        public double fixRate() { return vision == 0 ? 0 : (double) fixes / vision; }
        public int selfSamples() { return self.size(); }
        public int ballSamples() { return ball.size(); }
        public List<BeliefStats> stats() { return stats; }
    }

    /** Replays one recording (path prefix) with the given config. */
    public static Result run(Path prefix, LocalizationConfig config) throws IOException {
        List<String> perceptors = Recordings.perceptorMessages(prefix);
        List<GroundTruth.Line> truth = GroundTruth.read(Recordings.groundTruthFile(prefix));
        int type = 0;
        String team = "";
        Path eff = Recordings.effectorFile(prefix);
        if (Files.exists(eff)) {
            List<String> e = Files.readAllLines(eff, StandardCharsets.ISO_8859_1);
            for (int i = 0; i < Math.min(2, e.size()); i++) {
                Matcher m = SCENE.matcher(e.get(i));
                if (m.find() && m.group(1) != null) type = Integer.parseInt(m.group(1));
                Matcher t = TEAM.matcher(e.get(i));
                if (t.find()) team = t.group(1);
            }
        }
        BeliefStore store = new BeliefStore(FieldSpec.V066, config, NaoModel.ofType(type), team, null, 0);
        PerceptionParser parser = new PerceptionParser();
        Result r = new Result(prefix.getFileName().toString());
        int n = Math.min(perceptors.size(), truth.size());
        for (int i = 0; i < n; i++) {
            r.cycles++;
            Perception p;
            try {
                p = parser.parse(perceptors.get(i));
            } catch (MalformedMessageException ex) {
                r.malformed++;
                continue;
            }
            WorldBelief b = store.update(p);
            GroundTruth.Line g = truth.get(i);
            boolean fallen = g.hasTorso() && g.fallen();
            if (fallen) r.fallenCycles++;
            if (b.self() != null && g.hasTorso()) {
                Pose2 f = toField(b.self(), b.side());
                double err = Math.hypot(f.x() - g.x(), f.y() - g.y());
                if (fallen) r.fallenSelf.add(err);
                else {
                    r.self.add(err);
                    r.theta.add(Math.abs(Angles.difference(f.thetaDeg(), g.yawDeg())));
                }
            }
            if (b.ballGlobal() != null && g.hasBall()) {
                Vector2 ball = b.side() == Side.RIGHT ? b.ballGlobal().times(-1) : b.ballGlobal();
                r.ball.add(Math.hypot(ball.x() - g.ballX(), ball.y() - g.ballY()));
            }
        }
        r.vision = store.stats().visionFrames();
        r.fixes = store.stats().selfFixes();
        r.stats.add(store.stats());
        return r;
    }

    /** A pose in the team's own frame, in the field frame (right side: turned by 180°). */
    public static Pose2 toField(Pose2 own, Side side) {
        if (side != Side.RIGHT) return own;
        return new Pose2(-own.x(), -own.y(), Angles.normalize(own.thetaDeg() + 180));
    }

    static double quantile(List<Double> v, double q) {
        if (v.isEmpty()) return Double.NaN;
        double[] a = v.stream().mapToDouble(Double::doubleValue).toArray();
        Arrays.sort(a);
        int i = (int) Math.ceil(q * a.length) - 1;
        return a[Math.max(0, Math.min(a.length - 1, i))];
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** The command line; returns the exit status. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        LocalizationConfig config = LocalizationConfig.DEFAULT;
        boolean compare = false;
        List<Path> recordings = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "--filter" -> {
                    if (i + 1 >= args.length) return usage(err, "--filter needs fifo or ekf");
                    String f = args[++i].toUpperCase(Locale.ROOT);
                    try { config = config.withFilter(LocalizationConfig.Filter.valueOf(f)); }
                    catch (IllegalArgumentException e) { return usage(err, "unknown filter '" + args[i] + "' (fifo or ekf)"); }
                }
                case "--pairs" -> {
                    if (i + 1 >= args.length) return usage(err, "--pairs needs equal or geometry");
                    try { config = config.withPairWeighting(LocalizationConfig.PairWeighting.valueOf(args[++i].toUpperCase(Locale.ROOT))); }
                    catch (IllegalArgumentException e) { return usage(err, "unknown pair weighting '" + args[i] + "' (equal or geometry)"); }
                }
                case "--compare" -> compare = true;
                case "-h", "--help" -> { usage(out, null); return 0; }
                default -> {
                    if (a.startsWith("-")) return usage(err, "unknown option '" + a + "'");
                    Path p = Paths.get(a);
                    if (!Files.isRegularFile(Recordings.perceptorFile(p)))
                        return usage(err, "no recording at '" + a + "': " + Recordings.perceptorFile(p) + " is missing");
                    if (!Files.isRegularFile(Recordings.groundTruthFile(p)))
                        return usage(err, "recording '" + a + "' has no ground truth: " + Recordings.groundTruthFile(p) + " is missing");
                    recordings.add(p);
                }
            }
        }
        if (recordings.isEmpty()) return usage(err, "name at least one recording, e.g. ../shared/recordings/S1");
        try {
            if (compare) {
                out.println("filter    pairs     self_med  self_p95  self_max  theta_med  theta_p95  ball_med  ball_p95  fix_rate");
                Result def = null;
                for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
                    for (LocalizationConfig.PairWeighting w : LocalizationConfig.PairWeighting.values()) {
                        LocalizationConfig c = config.withFilter(f).withPairWeighting(w);
                        Result all = runAll(recordings, c, null);
                        out.printf(Locale.ROOT, "%-9s %-9s %8.3f  %8.3f  %8.3f  %9.2f  %9.2f  %8.3f  %8.3f  %8.3f%n",
                                f.name().toLowerCase(Locale.ROOT), w.name().toLowerCase(Locale.ROOT),
                                all.selfMedian(), all.selfP95(), all.selfMax(), all.thetaMedian(), all.thetaP95(),
                                all.ballMedian(), all.ballP95(), all.fixRate());
                        if (f == config.filter() && w == config.pairWeighting()) def = all;
                    }
                }
                out.println("(the summary below is the configured filter: " + config.filter().name().toLowerCase(Locale.ROOT)
                        + ", " + config.pairWeighting().name().toLowerCase(Locale.ROOT) + ")");
                summary(out, def);
            } else {
                out.println("filter=" + config.filter().name().toLowerCase(Locale.ROOT)
                        + " pairs=" + config.pairWeighting().name().toLowerCase(Locale.ROOT));
                summary(out, runAll(recordings, config, out));
            }
        } catch (IOException e) {
            err.println("localize-eval: " + e.getMessage());
            return 1;
        }
        return 0;
    }

    private static Result runAll(List<Path> recordings, LocalizationConfig config, PrintStream out) throws IOException {
        Result all = new Result("overall");
        for (Path p : recordings) {
            Result r = run(p, config);
            if (out != null) print(out, r);
            all.add(r);
        }
        if (out != null) print(out, all);
        return all;
    }

    private static void print(PrintStream out, Result r) {
        out.printf(Locale.ROOT, "%-10s self median %.3f p95 %.3f max %.3f m (%d cycles) | theta median %.2f p95 %.2f deg"
                        + " | ball median %.3f p95 %.3f m (%d cycles) | fix_rate %.3f (%d/%d vision frames)%n",
                r.name, r.selfMedian(), r.selfP95(), r.selfMax(), r.self.size(), r.thetaMedian(), r.thetaP95(),
                r.ballMedian(), r.ballP95(), r.ball.size(), r.fixRate(), r.fixes, r.vision);
        long noVision = 0, none = 0, one = 0, bad = 0, noId = 0, fallenFrames = 0;
        for (BeliefStats s : r.stats) {
            noVision += s.noVision(); none += s.noLandmark(); one += s.oneLandmark(); bad += s.badPolar();
            noId += s.playerWithoutId(); fallenFrames += s.fallenFrames();
        }
        out.printf(Locale.ROOT, "%-10s   skipped: no_vision=%d no_landmark=%d one_landmark=%d bad_distance=%d"
                        + " player_without_id=%d malformed=%d | fallen: %d cycles (torso > 45 deg), %d vision frames skipped (falling, down or shaken),"
                        + " self error while down median %.3f m (%d cycles, not in the figures above)%n",
                "", noVision, none, one, bad, noId, r.malformed, r.fallenCycles, fallenFrames,
                quantile(r.fallenSelf, 0.5), r.fallenSelf.size());
    }

    private static void summary(PrintStream out, Result r) {
        out.printf(Locale.ROOT, "self_median_m=%.3f self_p95_m=%.3f theta_median_deg=%.2f ball_median_m=%.3f ball_p95_m=%.3f fix_rate=%.3f%n",
                r.selfMedian(), r.selfP95(), r.thetaMedian(), r.ballMedian(), r.ballP95(), r.fixRate());
    }

    private static int usage(PrintStream s, String problem) {
        if (problem != null) s.println("localize-eval: " + problem);
        s.println("usage: scripts/phalanx bench localize [--filter fifo|ekf] [--pairs equal|geometry] [--compare] <recording>...");
        s.println("  a recording is a path prefix such as ../shared/recordings/S1 (needs X_perceptors.txt and X_groundtruth.txt)");
        return 2;
    }
}

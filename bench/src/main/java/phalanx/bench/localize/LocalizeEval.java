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
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.io.UncheckedIOException;
import java.util.stream.Stream;
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

    /**
     * One replayed cycle, as the figures see it. {@code k} is the perceptor line (1-based, the README's
     * message count); {@code believed} and {@code ballBelieved} are in the field frame (null: no belief);
     * {@code ballInView}: the ball was in a vision frame within the last {@link #BALL_VIEW_SECONDS};
     * {@code vision}: this line carried a vision frame (See).
     */
    public record Cycle(int k, GroundTruth.Line truth, boolean fallen, Pose2 believed, Vector2 ballBelieved,
                        boolean ballInView, boolean vision, boolean ballSeen) {
        /** {@code ballSeen}, whether this line's vision frame showed the ball, taken as {@code vision && ballInView}. */
        public Cycle(int k, GroundTruth.Line truth, boolean fallen, Pose2 believed, Vector2 ballBelieved, boolean ballInView, boolean vision) {
            this(k, truth, fallen, believed, ballBelieved, ballInView, vision, vision && ballInView);
        }
        /** A cycle that carried a vision frame (synthetic cycles in tests). */
        public Cycle(int k, GroundTruth.Line truth, boolean fallen, Pose2 believed, Vector2 ballBelieved, boolean ballInView) {
            this(k, truth, fallen, believed, ballBelieved, ballInView, true);
        }
        /** Self position error (m), NaN without a belief or a true torso. */
        public double selfError() {
            return believed == null || !truth.hasTorso() ? Double.NaN
                    : Math.hypot(believed.x() - truth.x(), believed.y() - truth.y());
        }
        /** Heading error (deg, absolute), NaN without a belief or a true torso. */
        public double headingError() {
            return believed == null || !truth.hasTorso() ? Double.NaN
                    : Math.abs(Angles.difference(believed.thetaDeg(), truth.yawDeg()));
        }
        /** Ball position error (m), NaN without a ball belief or a true ball. */
        public double ballError() {
            return ballBelieved == null || !truth.hasBall() ? Double.NaN
                    : Math.hypot(ballBelieved.x() - truth.ballX(), ballBelieved.y() - truth.ballY());
        }
        /** Counted in the self and heading figures: a belief, a true torso, upright. */
        public boolean countsForSelf() { return !fallen && Double.isFinite(selfError()); }
        /** Counted in the ball figures: a ball belief, a true ball, the ball seen within the last second. */
        public boolean countsForBall() { return ballInView && Double.isFinite(ballError()); }
    }

    /** The ball figures count a cycle only if a vision frame showed the ball within this many seconds. */
    public static final double BALL_VIEW_SECONDS = 1.0;

    /**
     * A move (beam, trainer or referee): the true torso jumps at least this far between two lines; walking
     * moves it about 0.01 m per cycle. After each the "recover" column counts the cycles (lines) from the
     * move until the self error is first at most {@link #RECOVERED_METRES} again (issue 19).
     */
    public static final double MOVE_METRES = 1.0, RECOVERED_METRES = 1.0;
    // max_seen and rec_seen (issue 19): the same figures without the cycles between a move and the first vision
    // frame after it (that frame's line included, so at least one frame shows the new pose). Before that frame no
    // filter can know of the move.

    /** The errors of one or more recordings. */
    public static final class Result {
        final String name;
        /** self and theta: upright cycles; ball: cycles with the ball in view in the last second; ballAll: every cycle with a ball belief. */
        final List<Double> self = new ArrayList<>(), seen = new ArrayList<>(), theta = new ArrayList<>(), ball = new ArrayList<>(), ballSeen = new ArrayList<>(),
                ballAll = new ArrayList<>(), fallenSelf = new ArrayList<>();
        final List<Cycle> cycleLog = new ArrayList<>();
        long cycles, malformed, fallenCycles, vision, fixes, selfOver1m, moves;
        /** Most cycles any move took to recover (-1: no move); the move under way and its cycles so far. */
        int recoverMax = -1, recovering = -1;
        /** The same from the first vision frame after each move on (-1: none); waiting: a move without a frame yet. */
        int seenRecoverMax = -1, seenRecovering = -1;
        boolean waiting;
        /** The replay fed the recording's odometry (a single recording's result). */
        boolean odometry;
        /** A ball jump (trainer or referee placement) not yet followed by a vision frame that shows the ball. */
        boolean ballWaiting;
        long ballJumps;
        private double lastX = Double.NaN, lastY = Double.NaN, lastBallX = Double.NaN, lastBallY = Double.NaN;
        final List<BeliefStats> stats = new ArrayList<>();

        Result(String name) { this.name = name; }

        /** Counts one cycle (the replay calls this once per perceptor line that parsed). */
        void observe(Cycle c) {
            cycleLog.add(c);
            GroundTruth.Line g = c.truth();
            if (g.hasTorso()) {
                if (Double.isFinite(lastX) && Math.hypot(g.x() - lastX, g.y() - lastY) >= MOVE_METRES) {
                    moves++;
                    if (recovering >= 0) recoverMax = Math.max(recoverMax, recovering);
                    recovering = 0;
                    if (seenRecovering >= 0) seenRecoverMax = Math.max(seenRecoverMax, seenRecovering);
                    seenRecovering = -1;
                    waiting = true;
                }
                lastX = g.x();
                lastY = g.y();
            }
            if (recovering >= 0) {
                if (c.selfError() <= RECOVERED_METRES) {
                    recoverMax = Math.max(recoverMax, recovering);
                    recovering = -1;
                } else {
                    recovering++;
                }
            }
            if (waiting && c.vision()) {
                waiting = false;
                seenRecovering = 0;
            }
            if (seenRecovering >= 0) {
                if (c.selfError() <= RECOVERED_METRES) {
                    seenRecoverMax = Math.max(seenRecoverMax, seenRecovering);
                    seenRecovering = -1;
                } else {
                    seenRecovering++;
                }
            }
            if (g.hasBall()) {
                if (Double.isFinite(lastBallX) && Math.hypot(g.ballX() - lastBallX, g.ballY() - lastBallY) >= MOVE_METRES) {
                    ballJumps++;
                    ballWaiting = true;
                }
                lastBallX = g.ballX();
                lastBallY = g.ballY();
            }
            if (ballWaiting && c.ballSeen()) ballWaiting = false;
            if (c.fallen()) fallenCycles++;
            double e = c.selfError();
            if (Double.isFinite(e)) {
                if (c.fallen()) fallenSelf.add(e);
                else {
                    self.add(e);
                    if (!waiting) seen.add(e);
                    theta.add(c.headingError());
                    if (e > 1.0) selfOver1m++;
                }
            }
            double be = c.ballError();
            if (Double.isFinite(be)) {
                ballAll.add(be);
                if (c.ballInView()) {
                    ball.add(be);
                    if (!ballWaiting) ballSeen.add(be);
                }
            }
        }

        void add(Result r) {
            self.addAll(r.self); seen.addAll(r.seen); theta.addAll(r.theta); ball.addAll(r.ball); ballAll.addAll(r.ballAll);
            ballSeen.addAll(r.ballSeen); ballJumps += r.ballJumps;
            fallenSelf.addAll(r.fallenSelf);
            cycles += r.cycles; malformed += r.malformed; fallenCycles += r.fallenCycles;
            vision += r.vision; fixes += r.fixes; selfOver1m += r.selfOver1m; stats.addAll(r.stats);
            moves += r.moves;
            recoverMax = Math.max(recoverMax, r.recoverCycles());
            seenRecoverMax = Math.max(seenRecoverMax, r.seenRecoverCycles());
        }

        public String name() { return name; }
        public long cycles() { return cycles; }
        public double selfMedian() { return quantile(self, 0.5); }
        public double selfP95() { return quantile(self, 0.95); }
        public double selfMax() { return quantile(self, 1.0); }
        /**
         * The self max without the cycles from a move until the first vision frame after it (issue 19): what a
         * filter could have known. Equal to {@link #selfMax} without a move.
         */
        public double selfMaxSeen() { return quantile(seen, 1.0); }
        public double thetaMedian() { return quantile(theta, 0.5); }
        public double thetaP95() { return quantile(theta, 0.95); }
        public double ballMedian() { return quantile(ball, 0.5); }
        public double ballP95() { return quantile(ball, 0.95); }
        public double ballMax() { return quantile(ball, 1.0); }
        /**
         * The ball p95 without the cycles from a jump of the true ball (1 m or more from one line to the next: a
         * trainer or referee placement; a 10 m/s ball moves 0.2 m a line) until the first vision frame that shows the
         * ball: what a filter could have known (issue 19's limit is on {@link #ballP95}, with them).
         */
        public double ballP95Seen() { return quantile(ballSeen, 0.95); }
        /** Jumps of the true ball by {@link #MOVE_METRES} or more from one line to the next. */
        public long ballJumps() { return ballJumps; }
        public double fixRate() { return vision == 0 ? 0 : (double) fixes / vision; }
        public int selfSamples() { return self.size(); }
        public int ballSamples() { return ball.size(); }
        /** Upright cycles whose self error is above 1 m. */
        public long selfOver1m() { return selfOver1m; }
        public List<BeliefStats> stats() { return stats; }
        /** Moves of the true torso by {@link #MOVE_METRES} or more from one line to the next. */
        public long moves() { return moves; }
        /**
         * The most cycles, over the moves, from a move's first line until the self error is at most
         * {@link #RECOVERED_METRES} (a move not recovered by the end counts to the end); -1 without a move.
         */
        public int recoverCycles() { return Math.max(recoverMax, recovering); }
        /**
         * The same counted from the first vision frame after each move (0: that frame's line is within
         * {@link #RECOVERED_METRES}); -1 without a move, or with no vision frame after it.
         */
        public int seenRecoverCycles() { return Math.max(seenRecoverMax, seenRecovering); }
        /** Every cycle of a single recording, in order (empty for a pooled result). */
        public List<Cycle> cycleLog() { return cycleLog; }

        /** The n counted cycles with the largest self error (ball: the largest ball error), worst first. */
        public List<Cycle> worst(int n, boolean byBall) {
            return cycleLog.stream().filter(byBall ? Cycle::countsForBall : Cycle::countsForSelf)
                    .sorted(java.util.Comparator.comparingDouble((Cycle c) -> byBall ? c.ballError() : c.selfError()).reversed())
                    .limit(n).toList();
        }
    }

    /**
     * The per-recording limits of issue 19: a recording at or above any of them is named in a
     * "breaks:" line. A figure that is NaN (no cycle counted) breaks nothing.
     */
    public record Limits(double selfP95, double selfMax, double headingP95Deg, double ballMedian, double ballP95) {
        public static final Limits ISSUE_19 = new Limits(0.3, 1.5, 10, 0.15, 0.6);

        /** The broken limits, in this order: self_p95, self_max, heading_p95, ball_median, ball_p95. */
        public List<String> broken(Result r) {
            List<String> out = new ArrayList<>();
            if (r.selfP95() >= selfP95) out.add("self_p95");
            if (r.selfMax() >= selfMax) out.add("self_max");
            if (r.thetaP95() >= headingP95Deg) out.add("heading_p95");
            if (r.ballMedian() >= ballMedian) out.add("ball_median");
            if (r.ballP95() >= ballP95) out.add("ball_p95");
            return out;
        }

        /** "self_max 3.964 >= 1.5 m, ..." for the broken limits. */
        public String describe(Result r) {
            List<String> parts = new ArrayList<>();
            for (String b : broken(r)) {
                parts.add(switch (b) {
                    case "self_p95" -> String.format(Locale.ROOT, "self_p95 %.3f >= %s m", r.selfP95(), num(selfP95));
                    case "self_max" -> String.format(Locale.ROOT, "self_max %.3f >= %s m", r.selfMax(), num(selfMax));
                    case "heading_p95" -> String.format(Locale.ROOT, "heading_p95 %.2f >= %s deg", r.thetaP95(), num(headingP95Deg));
                    case "ball_median" -> String.format(Locale.ROOT, "ball_median %.3f >= %s m", r.ballMedian(), num(ballMedian));
                    default -> String.format(Locale.ROOT, "ball_p95 %.3f >= %s m", r.ballP95(), num(ballP95));
                });
            }
            return String.join(", ", parts);
        }

        private static String num(double v) { return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v); }
    }

    /** Replays one recording (path prefix) with the given config. */
    public static Result run(Path prefix, LocalizationConfig config) throws IOException { return run(prefix, config, true); }

    /**
     * Replays one recording; with {@code useOdometry} and an {@code X_odometry.txt(.gz)} beside it (the project's
     * recordings have one: the walk's commanded motion per cycle), each cycle's odometry is passed to
     * {@code BeliefStore.odometry} after its update, as the agent does; without, the belief moves only with vision.
     */
    public static Result run(Path prefix, LocalizationConfig config, boolean useOdometry) throws IOException {
        List<String> perceptors = Recordings.perceptorMessages(prefix);
        List<GroundTruth.Line> truth = GroundTruth.read(Recordings.groundTruthFile(prefix));
        int type = 0;
        String team = "";
        Path eff = Recordings.effectorFile(prefix);
        if (Files.exists(eff)) {
            List<String> e = Recordings.lines(eff);
            for (int i = 0; i < Math.min(2, e.size()); i++) {
                Matcher m = SCENE.matcher(e.get(i));
                if (m.find() && m.group(1) != null) type = Integer.parseInt(m.group(1));
                Matcher t = TEAM.matcher(e.get(i));
                if (t.find()) team = t.group(1);
            }
        }
        if (perceptors.size() != truth.size()) {
            throw new IOException(prefix.getFileName() + ": " + perceptors.size() + " perceptor lines but " + truth.size()
                    + " ground-truth lines (" + Recordings.perceptorFile(prefix) + ", " + Recordings.groundTruthFile(prefix)
                    + "); one ground-truth line per perceptor line is the format, so one of them is truncated");
        }
        double[][] odometry = useOdometry ? odometry(prefix, perceptors.size()) : null;
        BeliefStore store = new BeliefStore(FieldSpec.V066, config, NaoModel.ofType(type), team, null, 0);
        PerceptionParser parser = new PerceptionParser();
        Result r = new Result(prefix.getFileName().toString());
        r.odometry = odometry != null;
        int n = perceptors.size();
        double ballSeenAt = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            r.cycles++;
            Perception p;
            try {
                p = parser.parse(perceptors.get(i));
            } catch (MalformedMessageException ex) {
                r.malformed++;
                if (odometry != null) store.odometry(odometry[i][0], odometry[i][1], odometry[i][2]);
                continue;
            }
            WorldBelief b = store.update(p);
            if (odometry != null) store.odometry(odometry[i][0], odometry[i][1], odometry[i][2]);
            GroundTruth.Line g = truth.get(i);
            double now = Double.isFinite(p.time()) ? p.time() : g.now();
            if (p.hasVision() && p.vision().ball() != null) ballSeenAt = now;
            boolean fallen = g.hasTorso() && g.fallen();
            Pose2 self = b.self() == null ? null : toField(b.self(), b.side());
            Vector2 ball = b.ballGlobal() == null ? null : b.side() == Side.RIGHT ? b.ballGlobal().times(-1) : b.ballGlobal();
            r.observe(new Cycle(i + 1, g, fallen, self, ball, now - ballSeenAt <= BALL_VIEW_SECONDS + 1e-9, p.hasVision(),
                    p.hasVision() && p.vision().ball() != null));
        }
        r.vision = store.stats().visionFrames();
        r.fixes = store.stats().selfFixes();
        r.stats.add(store.stats());
        return r;
    }

    /**
     * The recording's odometry file, one {@code forward left turnDeg} line per perceptor line after {@code #} lines;
     * null when it has none. A file of another length, or a bad line, is an IOException naming it.
     */
    static double[][] odometry(Path prefix, int lines) throws IOException {
        Path f = Recordings.odometryFile(prefix);
        if (!Files.isRegularFile(f)) return null;
        List<double[]> out = new ArrayList<>();
        int n = 0;
        for (String s : Recordings.lines(f)) {
            n++;
            if (s.isBlank() || s.startsWith("#")) continue;
            String[] v = s.trim().split("\\s+");
            if (v.length != 3) throw new IOException(f + ":" + n + ": expected 3 fields (forward left turn_deg), found " + v.length);
            try {
                out.add(new double[] {Double.parseDouble(v[0]), Double.parseDouble(v[1]), Double.parseDouble(v[2])});
            } catch (NumberFormatException e) {
                throw new IOException(f + ":" + n + ": not a number: " + e.getMessage());
            }
        }
        if (out.size() != lines) {
            throw new IOException(prefix.getFileName() + ": " + lines + " perceptor lines but " + out.size() + " odometry lines ("
                    + f + "); one odometry line per perceptor line is the format, so one of them is truncated");
        }
        return out.toArray(new double[0][]);
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
        boolean compare = false, tsv = false, detail = false, oneFilter = false, useOdometry = true;
        int worst = 0;
        List<Path> recordings = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "--filter" -> {
                    if (i + 1 >= args.length) return usage(err, "--filter needs fifo or ekf");
                    String f = args[++i].toUpperCase(Locale.ROOT);
                    try { config = config.withFilter(LocalizationConfig.Filter.valueOf(f)); }
                    catch (IllegalArgumentException e) { return usage(err, "unknown filter '" + args[i] + "' (fifo or ekf)"); }
                    oneFilter = true;
                }
                case "--pairs" -> {
                    if (i + 1 >= args.length) return usage(err, "--pairs needs equal or geometry");
                    try { config = config.withPairWeighting(LocalizationConfig.PairWeighting.valueOf(args[++i].toUpperCase(Locale.ROOT))); }
                    catch (IllegalArgumentException e) { return usage(err, "unknown pair weighting '" + args[i] + "' (equal or geometry)"); }
                }
                case "--worst" -> {
                    if (i + 1 >= args.length) return usage(err, "--worst needs a number of cycles");
                    try { worst = Integer.parseInt(args[++i]); } catch (NumberFormatException e) { worst = -1; }
                    if (worst < 0) return usage(err, "--worst needs a number of cycles >= 0, not '" + args[i] + "'");
                }
                case "--compare" -> compare = true;
                case "--no-odometry" -> useOdometry = false;
                case "--all" -> {
                    Path own = projectRecordings();
                    try {
                        List<Path> mine = withGroundTruth(own);
                        if (mine.isEmpty()) err.println("localize-eval: no recording with ground truth in the project's " + own);
                        recordings.addAll(mine);
                        Optional<Path> shared = Recordings.dir();
                        if (shared.isEmpty()) err.println("localize-eval: " + Recordings.missingMessage().replace("; skipped", "") + "; only the project's recordings");
                        else recordings.addAll(withGroundTruth(shared.get()));
                    } catch (IOException e) {
                        err.println("localize-eval: cannot list recordings: " + e.getMessage());
                        return 1;
                    }
                }
                case "--tsv" -> tsv = true;
                case "--detail" -> detail = true;
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
        if (recordings.isEmpty()) return usage(err, "name at least one recording, e.g. ../shared/recordings/S1, or --all");
        List<String> skipped = new ArrayList<>();
        try {
            if (compare) {
                out.println("filter    pairs     self_med  self_p95  self_max  theta_med  theta_p95  ball_med  ball_p95  fix_rate");
                Result def = null;
                for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
                    for (LocalizationConfig.PairWeighting w : LocalizationConfig.PairWeighting.values()) {
                        LocalizationConfig c = config.withFilter(f).withPairWeighting(w);
                        Result all = pooled(runEach(recordings, c, useOdometry, skipped, err));
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
                return skippedStatus(skipped, err);
            }
            List<LocalizationConfig.Filter> filters = oneFilter ? List.of(config.filter())
                    : List.of(LocalizationConfig.Filter.values());
            if (tsv) out.println(String.join("\t", TSV_HEADER));
            Result def = null;
            for (LocalizationConfig.Filter f : filters) {
                LocalizationConfig c = config.withFilter(f);
                List<Result> each = runEach(recordings, c, useOdometry, skipped, err);
                Result all = pooled(each);
                if (f == config.filter()) def = all;
                String label = f.name().toLowerCase(Locale.ROOT) + "/" + c.pairWeighting().name().toLowerCase(Locale.ROOT);
                if (tsv) {
                    for (Result r : each) out.println(tsvRow(label, r));
                    out.println(tsvRow(label, all));
                    continue;
                }
                List<String> withOdometry = each.stream().filter(x -> x.odometry).map(Result::name).toList();
                if (!withOdometry.isEmpty()) out.println("(the walk's odometry fed after each update, as the agent does, on: "
                        + String.join(", ", withOdometry) + "; --no-odometry replays them without)");
                table(out, label, each, all, Limits.ISSUE_19, worst);
                if (detail) for (Result r : each) detail(out, r);
            }
            if (!tsv) {
                out.println("(summary: " + config.filter().name().toLowerCase(Locale.ROOT) + ", "
                        + config.pairWeighting().name().toLowerCase(Locale.ROOT) + ", all recordings pooled)");
                summary(out, def);
            }
        } catch (UncheckedIOException e) {
            err.println("localize-eval: " + e.getMessage());
            return 1;
        }
        return skippedStatus(skipped, err);
    }

    /** 0, or 1 after naming the recordings that could not be read (each once; they are in no figure above). */
    private static int skippedStatus(List<String> skipped, PrintStream err) {
        if (skipped.isEmpty()) return 0;
        err.println("localize-eval: " + skipped.size() + " recording(s) could not be read and are in no figure: "
                + String.join(", ", skipped));
        return 1;
    }

    /**
     * The project's own recordings (recordings/README.md, made with scripts/phalanx bench record): {@code recordings/}
     * under {@code phalanx.root} (scripts/lib/run-java sets it), else under the working directory.
     */
    public static Path projectRecordings() {
        return Path.of(System.getProperty("phalanx.root", ".")).toAbsolutePath().normalize().resolve("recordings");
    }

    /**
     * The recordings in a folder that have a ground truth, as path prefixes, sorted by name: every
     * {@code X_perceptors.txt} or {@code X_perceptors.txt.gz} with an {@code X_groundtruth.txt(.gz)} beside it.
     * A missing folder has none.
     */
    public static List<Path> withGroundTruth(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString())
                    .map(n -> n.endsWith("_perceptors.txt") ? n.substring(0, n.length() - "_perceptors.txt".length())
                            : n.endsWith("_perceptors.txt.gz") ? n.substring(0, n.length() - "_perceptors.txt.gz".length()) : null)
                    .filter(n -> n != null).distinct().sorted()
                    .map(dir::resolve)
                    .filter(p -> Files.isRegularFile(Recordings.groundTruthFile(p)))
                    .toList();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    /** Replays each recording on its own. */
    static List<Result> runEach(List<Path> recordings, LocalizationConfig config) throws IOException {
        List<Result> out = new ArrayList<>();
        for (Path p : recordings) out.add(run(p, config));
        return out;
    }

    /**
     * The same, but a recording that cannot be read (truncated, bad line) is left out with a message on {@code err}
     * (once, the first time) and its name added to {@code skipped}; the others are measured.
     */
    static List<Result> runEach(List<Path> recordings, LocalizationConfig config, boolean useOdometry, List<String> skipped, PrintStream err) {
        List<Result> out = new ArrayList<>();
        for (Path p : recordings) {
            String name = p.getFileName().toString();
            try {
                out.add(run(p, config, useOdometry));
            } catch (IOException | RuntimeException e) {
                if (!skipped.contains(name)) {
                    skipped.add(name);
                    err.println("localize-eval: left out " + p + ": " + e.getMessage());
                }
            }
        }
        return out;
    }

    /** All recordings' errors in one (the "pooled" line). */
    static Result pooled(List<Result> each) {
        Result all = new Result("pooled");
        for (Result r : each) all.add(r);
        return all;
    }

    static final String TABLE_HEADER = String.format(Locale.ROOT, "%-16s %6s %6s %8s %8s %8s %8s %6s %8s %8s %8s %8s %7s %5s %7s %8s %8s %7s %8s",
            "recording", "cycles", "self_n", "self_med", "self_p95", "self_max", "hdg_p95", "ball_n", "ball_med",
            "ball_p95", "ball_max", "fix_rate", "self>1m", "moves", "recover", "max_seen", "rec_seen", "b_jumps", "b95_seen");

    /** One table line: metres, heading in degrees; ball over cycles with the ball in view in the last second. */
    static String row(Result r) {
        return String.format(Locale.ROOT, "%-16s %6d %6d %8.3f %8.3f %8.3f %8.2f %6d %8.3f %8.3f %8.3f %8.3f %7d %5d %7s %8.3f %8s %7d %8.3f",
                r.name, r.cycles, r.self.size(), r.selfMedian(), r.selfP95(), r.selfMax(), r.thetaP95(),
                r.ball.size(), r.ballMedian(), r.ballP95(), r.ballMax(), r.fixRate(), r.selfOver1m, r.moves,
                recover(r), r.selfMaxSeen(), recoverSeen(r), r.ballJumps, r.ballP95Seen());
    }

    /** One filter's block: header, one line per recording, the pooled line, the breaks, the worst cycles. */
    static void table(PrintStream out, String label, List<Result> each, Result all, Limits limits, int worst) {
        out.println("filter " + label + "  (m, heading deg; ball only over cycles with the ball seen in the last "
                + num1(BALL_VIEW_SECONDS) + " s; limits: self_p95 < " + limits.selfP95() + ", self_max < " + limits.selfMax()
                + ", heading_p95 < " + limits.headingP95Deg() + ", ball_median < " + limits.ballMedian()
                + ", ball_p95 < " + limits.ballP95() + ")");
        out.println(TABLE_HEADER);
        for (Result r : each) out.println(row(r));
        out.println(row(all));
        boolean any = false;
        for (Result r : each) {
            if (limits.broken(r).isEmpty()) continue;
            any = true;
            out.println("breaks: " + r.name + ": " + limits.describe(r));
        }
        if (!any) out.println("breaks: none");
        if (worst <= 0) return;
        for (Result r : each) {
            List<String> b = limits.broken(r);
            if (b.isEmpty()) continue;
            boolean selfBroken = b.stream().anyMatch(x -> !x.startsWith("ball"));
            boolean ballBroken = b.stream().anyMatch(x -> x.startsWith("ball"));
            if (selfBroken) worstCycles(out, r, worst, false);
            if (ballBroken) worstCycles(out, r, worst, true);
        }
    }

    /** The worst cycles of one recording: cycle k (perceptor line), time, true and believed pose (field frame) and ball. */
    static void worstCycles(PrintStream out, Result r, int n, boolean byBall) {
        out.println("worst " + n + " cycles of " + r.name + " by " + (byBall ? "ball" : "self") + " error"
                + " (k = perceptor line; pose x y yaw_deg, field frame):");
        for (Cycle c : r.worst(n, byBall)) {
            GroundTruth.Line g = c.truth();
            Pose2 s = c.believed();
            out.printf(Locale.ROOT, "  k=%4d now %6.2f  true (%7.3f %7.3f %7.1f) believed %s  self %.3f m hdg %.1f deg"
                            + " | ball true (%7.3f %7.3f) believed %s err %.3f m%n",
                    c.k(), g.now(), g.x(), g.y(), g.yawDeg(),
                    s == null ? "(none)" : String.format(Locale.ROOT, "(%7.3f %7.3f %7.1f)", s.x(), s.y(), s.thetaDeg()),
                    c.selfError(), c.headingError(), g.ballX(), g.ballY(),
                    c.ballBelieved() == null ? "(none)" : String.format(Locale.ROOT, "(%7.3f %7.3f)", c.ballBelieved().x(), c.ballBelieved().y()),
                    c.ballError());
        }
    }

    static final String[] TSV_HEADER = {"filter", "recording", "cycles", "self_n", "self_median_m", "self_p95_m", "self_max_m",
            "heading_p95_deg", "ball_n", "ball_median_m", "ball_p95_m", "ball_max_m", "fix_rate", "self_over_1m", "moves", "recover_cycles", "self_max_seen_m", "recover_seen_cycles", "ball_jumps", "ball_p95_seen_m", "breaks"};

    static String tsvRow(String label, Result r) {
        List<String> b = Limits.ISSUE_19.broken(r);
        return String.join("\t", label, r.name, Long.toString(r.cycles), Integer.toString(r.self.size()),
                f3(r.selfMedian()), f3(r.selfP95()), f3(r.selfMax()), String.format(Locale.ROOT, "%.2f", r.thetaP95()),
                Integer.toString(r.ball.size()), f3(r.ballMedian()), f3(r.ballP95()), f3(r.ballMax()), f3(r.fixRate()),
                Long.toString(r.selfOver1m), Long.toString(r.moves), recover(r), f3(r.selfMaxSeen()), recoverSeen(r), Long.toString(r.ballJumps), f3(r.ballP95Seen()), b.isEmpty() ? "-" : String.join(",", b));
    }

    /** The recover figure: cycles, or "-" without a move. */
    static String recover(Result r) { return r.recoverCycles() < 0 ? "-" : Integer.toString(r.recoverCycles()); }

    /** The rec_seen figure: cycles from the first vision frame after a move, or "-". */
    static String recoverSeen(Result r) { return r.seenRecoverCycles() < 0 ? "-" : Integer.toString(r.seenRecoverCycles()); }

    private static String f3(double v) { return String.format(Locale.ROOT, "%.3f", v); }
    private static String num1(double v) { return String.format(Locale.ROOT, "%.1f", v); }

    private static void detail(PrintStream out, Result r) {
        long noVision = 0, none = 0, one = 0, bad = 0, noId = 0, fallenFrames = 0, starts = 0, missed = 0;
        for (BeliefStats s : r.stats) {
            noVision += s.noVision(); none += s.noLandmark(); one += s.oneLandmark(); bad += s.badPolar();
            noId += s.playerWithoutId(); fallenFrames += s.fallenFrames(); starts += s.selfStarts(); missed += s.ballsMissed();
        }
        out.printf(Locale.ROOT, "%-16s skipped: no_vision=%d no_landmark=%d one_landmark=%d bad_distance=%d"
                        + " player_without_id=%d malformed=%d | fallen: %d cycles (torso > 45 deg), %d vision frames skipped (falling, down or shaken),"
                        + " self error while down median %.3f m (%d cycles, not in the figures above) | ball over every cycle with a belief: median %.3f p95 %.3f m (%d cycles)"
                        + " | self filter starts %d (the first and every re-initialisation) | ball dropped %d times (not seen in view)%n",
                r.name, noVision, none, one, bad, noId, r.malformed, r.fallenCycles, fallenFrames,
                quantile(r.fallenSelf, 0.5), r.fallenSelf.size(), quantile(r.ballAll, 0.5), quantile(r.ballAll, 0.95), r.ballAll.size(),
                starts, missed);
    }

    private static void summary(PrintStream out, Result r) {
        out.printf(Locale.ROOT, "self_median_m=%.3f self_p95_m=%.3f theta_median_deg=%.2f ball_median_m=%.3f ball_p95_m=%.3f fix_rate=%.3f%n",
                r.selfMedian(), r.selfP95(), r.thetaMedian(), r.ballMedian(), r.ballP95(), r.fixRate());
    }

    private static int usage(PrintStream s, String problem) {
        if (problem != null) s.println("localize-eval: " + problem);
        s.println("usage: scripts/phalanx bench localize [--filter fifo|ekf] [--pairs equal|geometry] [--worst N] [--tsv] [--detail] [--compare] [--all] [--no-odometry] <recording>...");
        s.println("  a recording is a path prefix such as ../shared/recordings/S1 (needs X_perceptors.txt and X_groundtruth.txt, either may be .gz)");
        s.println("  X_odometry.txt(.gz), where a recording has one, is fed to the belief store after each update; --no-odometry: not");
        s.println("  --all: every recording with ground truth in the project's recordings/ and in ../shared/recordings (when it is there)");
        s.println("  default: one block per filter (fifo, ekf): a line per recording, the pooled line, the recordings that break");
        s.println("  issue 19's limits; --filter runs one; --worst N prints the N worst cycles of each breaking recording;");
        s.println("  --tsv the same figures tab-separated; --detail the skip counters; --compare the pooled figures of all four choices");
        return 2;
    }
}

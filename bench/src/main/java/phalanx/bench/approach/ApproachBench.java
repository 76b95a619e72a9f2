package phalanx.bench.approach;

import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.wire.ServerConnection;
import phalanx.match.ServerProcess;
import phalanx.match.SessionProcess;
import phalanx.model.robot.NaoModel;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * scripts/phalanx bench approach (issue 18's in-game kick trial): the whole player, as it plays, alone on the
 * left of its own rcssserver3d (agent-sync, no real time), and a trainer on the monitor port that puts the
 * ball still 1-3 m from wherever the robot is, at a random bearing, and watches (ground truth) how long the
 * player takes to touch it and where the ball ends. Alone, the player goes On Ball by its own choice (the
 * coordinator is quiet: FieldPlayerBehaviour's fallback within 5 m), so this is game speed and the game's
 * approach, alignment and kick; nothing is set up for it. Balls are put at least {@code --goal-clearance}
 * from the opponent goal, so that a player that dribbles near the goal (--dribble-within) kicks here; a robot
 * with no room left around it is moved back to its own half.
 *
 * <p>Per trial one line; at the end medians of the time to the first touch and of the ball's travel, the
 * share of trials whose ball went over 6 m (the game figure) and over 8 m, the direction error
 * against the line to the goal's centre, and falls. Player options (--dribble-within, ...) go through
 * {@code --player-opts}, the player's own log to {@code --dir}.
 */
public final class ApproachBench {
    static final double FIELD_X = 15, FIELD_Y = 10, GOAL_HALF_WIDTH = 1.05;

    record Options(int unum, int type, int trials, double minM, double maxM, long seed, String playerOpts, Path dir,
                   int port, double noTouchS, double afterTouchS, double goalClearance, double bearingDeg,
                   double attackMinM, double attackMaxM) {
        /** The attack trial: the robot is moved A..B m from the opponent goal before each ball (NaN: off). */
        boolean attack() { return !Double.isNaN(attackMinM); }
    }

    static final String USAGE = """
            usage: scripts/phalanx bench approach [--trials N] [--type T] [--unum U] [--min M] [--max M] [--seed S]
                                                 [--player-opts "FLAGS"] [--dir DIR] [--port P] [--no-touch S]
                                                 [--after-touch S] [--goal-clearance M] [--bearing DEG]
                                                 [--attack A,B]
              starts its own rcssserver3d (agent port P, default the first free pair from 3700; monitor P+100)
              and one player (scripts/start.sh --only U, type T) and runs N trials (default 30): a still ball
              M_min..M_max m (default 1..3) from the robot, within DEG (default 50) of its heading: in view,
              as the ball is for the player the coordinator sends to it; a trial ends 1 s after the ball stopped, S s (default
              30) with no touch, or S s (default 12) after the first touch.
              --attack A,B: before each ball the robot is moved A..B m from the opponent goal's centre (within 40 deg of
              the field's axis), facing the goal within DEG/2, and the ball put M_min..M_max m ahead of it; a goal
              ends the trial, else the ball out or the touch limit (give --after-touch room to walk the ball in, e.g. 25),
              not a still ball. The goal-clearance is not applied.""";

    /** Parses the flags; a bad one throws IllegalArgumentException naming it. */
    static Options parse(String... args) {
        int unum = 9, type = 0, trials = 30, port = 0;
        double min = 1, max = 3, noTouch = 30, afterTouch = 12, clearance = 9, bearing = 50, attackMin = Double.NaN, attackMax = Double.NaN;
        long seed = 1;
        String opts = "";
        Path dir = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("-h") || a.equals("--help")) throw new IllegalArgumentException("help");
            if (i + 1 >= args.length) throw new IllegalArgumentException(a + " needs a value");
            String v = args[++i];
            try {
                switch (a) {
                    case "--unum" -> unum = Integer.parseInt(v);
                    case "--type" -> type = Integer.parseInt(v);
                    case "--trials" -> trials = Integer.parseInt(v);
                    case "--port" -> port = Integer.parseInt(v);
                    case "--min" -> min = Double.parseDouble(v);
                    case "--max" -> max = Double.parseDouble(v);
                    case "--seed" -> seed = Long.parseLong(v);
                    case "--no-touch" -> noTouch = Double.parseDouble(v);
                    case "--after-touch" -> afterTouch = Double.parseDouble(v);
                    case "--goal-clearance" -> clearance = Double.parseDouble(v);
                    case "--bearing" -> bearing = Double.parseDouble(v);
                    case "--attack" -> {
                        String[] ab = v.split(",", -1);
                        if (ab.length != 2) throw new IllegalArgumentException("--attack takes A,B (metres from the opponent goal), got '" + v + "'");
                        attackMin = Double.parseDouble(ab[0]);
                        attackMax = Double.parseDouble(ab[1]);
                    }
                    case "--player-opts" -> opts = v;
                    case "--dir" -> dir = Path.of(v);
                    default -> throw new IllegalArgumentException("unknown option " + a);
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(a + " needs a number, got '" + v + "'");
            }
        }
        if (unum < 2 || unum > 11) throw new IllegalArgumentException("--unum must be a field player, 2-11, got " + unum);
        if (type < 0 || type > 4) throw new IllegalArgumentException("--type must be 0-4, got " + type);
        if (trials < 1 || trials > 1000) throw new IllegalArgumentException("--trials must be 1-1000, got " + trials);
        if (!(min >= 0.3 && max >= min && max <= 5))
            throw new IllegalArgumentException("--min/--max must satisfy 0.3 <= min <= max <= 5 (the player goes On Ball within 5 m), got " + min + ", " + max);
        if (port != 0 && (port < 1024 || port > 65435)) throw new IllegalArgumentException("--port must be 1024-65435, got " + port);
        if (!(noTouch > 0 && afterTouch > 0)) throw new IllegalArgumentException("--no-touch and --after-touch must be positive");
        if (!(clearance >= 0 && clearance <= 20)) throw new IllegalArgumentException("--goal-clearance must be 0-20 m, got " + clearance);
        if (!(bearing >= 0 && bearing <= 180)) throw new IllegalArgumentException("--bearing must be 0-180 degrees, got " + bearing);
        if (!Double.isNaN(attackMin) && !(attackMin >= 2 && attackMax >= attackMin && attackMax <= 20))
            throw new IllegalArgumentException("--attack A,B must satisfy 2 <= A <= B <= 20 m, got " + attackMin + "," + attackMax);
        if (opts.matches(".*['\"\\\\$`;|&<>].*")) throw new IllegalArgumentException("--player-opts takes plain flags, got '" + opts + "'");
        return new Options(unum, type, trials, min, max, seed, opts, dir, port, noTouch, afterTouch, clearance, bearing, attackMin, attackMax);
    }

    /**
     * One trial: where the ball was put (distance and bearing from the robot), what became of it.
     * {@code movedFalls} are the falls in the 3 s after the bench moved a robot that had no room for a
     * ball around it: the move sets a walking robot down mid-stride, and 4 of 10 falls of a 30-trial
     * run came from it (docs/matches.md, session 20), so they are not the player's.
     */
    record Trial(int n, double distance, double bearingDeg, String end, double timeToTouch, double travel,
                 double directionErrorDeg, int falls, int movedFalls) {
        String line() {
            return String.format(Locale.ROOT, "trial %2d  ball %.2f m at %+5.0f deg  %-8s  touch after %5.1f s  travel %5.2f m  off the goal line %5.1f deg  falls %d%s",
                    n, distance, bearingDeg, end, timeToTouch, travel, directionErrorDeg, falls,
                    movedFalls > 0 ? " (+" + movedFalls + " after the bench moved it)" : "");
        }
    }

    /** The summary line of a run (medians over the touched trials). */
    static String summary(List<Trial> trials) {
        double[] touch = trials.stream().filter(t -> !Double.isNaN(t.timeToTouch())).mapToDouble(Trial::timeToTouch).toArray();
        double[] travel = trials.stream().filter(t -> !Double.isNaN(t.timeToTouch())).mapToDouble(Trial::travel).toArray();
        double[] err = trials.stream().filter(t -> !Double.isNaN(t.directionErrorDeg())).mapToDouble(t -> Math.abs(t.directionErrorDeg())).toArray();
        long over6 = trials.stream().filter(t -> t.travel() > 6).count(), over8 = trials.stream().filter(t -> t.travel() > 8).count();
        long goals = trials.stream().filter(t -> t.end().equals("goal")).count();
        int falls = trials.stream().mapToInt(Trial::falls).sum(), moved = trials.stream().mapToInt(Trial::movedFalls).sum();
        return String.format(Locale.ROOT, "approach trials=%d touched=%d time_to_touch_median_s=%.1f time_to_touch_p90_s=%.1f travel_median_m=%.2f"
                        + " over_6m=%d over_8m=%d goals=%d direction_error_median_deg=%.1f falls=%d falls_after_bench_move=%d",
                trials.size(), touch.length, median(touch), quantile(touch, 0.9), median(travel), over6, over8, goals, median(err), falls, moved);
    }

    static double median(double[] v) { return quantile(v, 0.5); }

    /** Linear-interpolated quantile; NaN for none. */
    static double quantile(double[] v, double q) {
        if (v.length == 0) return Double.NaN;
        double[] s = v.clone();
        Arrays.sort(s);
        double at = q * (s.length - 1);
        int lo = (int) Math.floor(at), hi = (int) Math.ceil(at);
        return s[lo] + (s[hi] - s[lo]) * (at - lo);
    }

    /** Signed difference a - b in (-180, 180]. */
    static double angleDiff(double a, double b) {
        double d = (a - b) % 360;
        if (d > 180) d -= 360;
        if (d <= -180) d += 360;
        return d;
    }

    // --- the run ---------------------------------------------------------------------------------------

    private final Options o;
    private final ServerConnection mon;
    private final MonitorScene scene = new MonitorScene();
    private final Random rnd;
    private final double standingZ;

    private ApproachBench(Options o, ServerConnection mon) {
        this.o = o;
        this.mon = mon;
        this.rnd = new Random(o.seed());
        this.standingZ = NaoModel.ofType(o.type()).standingTorsoHeight();
    }

    private void next() throws IOException {
        try {
            mon.reader().next();
        } catch (IOException e) {
            throw new IOException(String.format(Locale.ROOT, "the monitor connection: %s (after %d messages, game time %.2f s)", e.getMessage(),
                    scene.messages(), scene.time()), e);
        }
        try {
            scene.apply(mon.reader().text());
        } catch (IllegalArgumentException e) {
            System.err.println("approach-bench: a monitor message it could not read: " + e.getMessage());
        }
    }

    private MonitorScene.Pose torso() { return scene.torso(o.unum(), "Left"); }

    private boolean fallen() {
        MonitorScene.Pose p = torso();
        return p != null && (p.upZ() < 0.5 || p.z() < 0.5 * standingZ);
    }

    /** Game seconds of pictures, counting falls (edges). */
    private int pass(double seconds) throws IOException {
        double end = scene.time() + seconds;
        int falls = 0;
        boolean down = fallen();
        while (scene.time() < end) {
            next();
            boolean f = fallen();
            if (f && !down) falls++;
            down = f;
        }
        return falls;
    }

    /** A ball spot around the robot, or null when there is no room for one (the field's edge or the goal). */
    private double[] spot(MonitorScene.Pose p) {
        for (int k = 0; k < 200; k++) {
            double d = o.minM() + rnd.nextDouble() * (o.maxM() - o.minM());
            double b = o.bearingDeg() * (2 * rnd.nextDouble() - 1);
            double h = Math.toRadians(p.yawDeg() + b);
            double x = p.x() + d * Math.cos(h), y = p.y() + d * Math.sin(h);
            if (Math.abs(x) > FIELD_X - 3 || Math.abs(y) > FIELD_Y - 2) continue;
            if (!o.attack() && Math.hypot(FIELD_X - x, y) < o.goalClearance()) continue;
            return new double[]{x, y, d, b};
        }
        return null;
    }

    /** The attack trial's start: the robot A..B m from the opponent goal, facing it; the falls of the 3 s after the move. */
    /** SimSpark's RuleGoalPauseTime (naosoccersim.rb), game seconds. */
    private static final double GOAL_PAUSE_S = 3.0;
    private boolean afterGoal;

    private int moveToAttack() throws IOException {
        double r = o.attackMinM() + rnd.nextDouble() * (o.attackMaxM() - o.attackMinM());
        double phi = Math.toRadians(40 * (2 * rnd.nextDouble() - 1));
        double x = FIELD_X - r * Math.cos(phi), y = r * Math.sin(phi);
        double h = Math.toDegrees(Math.atan2(-y, FIELD_X - x)) + o.bearingDeg() / 2 * (2 * rnd.nextDouble() - 1);
        // After a goal the server holds Goal_Left for its goal pause (RuleGoalPauseTime, 3 s; a PlayOn sent then does not
        // hold) and then gives the kick-off, in which the player beams back to its formation spot: wait for that beam,
        // then play on and move it.
        int falls = afterGoal ? pass(GOAL_PAUSE_S + 0.5) : 0;
        afterGoal = false;
        mon.send("(playMode PlayOn)");
        falls += pass(0.5);
        // the move's angle 0 faces +y (recordings README)
        mon.send(String.format(Locale.ROOT, "(agent (unum %d) (team Left) (move %.3f %.3f %.3f %.1f))", o.unum(), x, y, standingZ, h - 90));
        return falls + pass(3);
    }

    private Trial trial(int n) throws IOException {
        int falls = 0, movedFalls = 0;
        if (torso() == null) throw new IOException("player " + o.unum() + " is no longer on the field (its process died? see its log)");
        if (o.attack()) movedFalls = moveToAttack();
        double[] s = spot(torso());
        if (s == null) {
            double x = -6 + 4 * rnd.nextDouble(), y = -3 + 6 * rnd.nextDouble(), h = -180 + 360 * rnd.nextDouble();
            // the move's angle 0 faces +y (recordings README)
            mon.send(String.format(Locale.ROOT, "(agent (unum %d) (team Left) (move %.3f %.3f %.3f %.1f))", o.unum(), x, y, standingZ, h - 90));
            movedFalls = pass(3);
            s = spot(torso());
            if (s == null) throw new IOException("no room for a ball around the robot even after moving it to (" + x + ", " + y + ")");
        }
        mon.send(String.format(Locale.ROOT, "(ball (pos %.3f %.3f 0.042)(vel 0 0 0))", s[0], s[1]));
        mon.send("(playMode PlayOn)");
        // the first picture that shows the ball where it was put starts the clock
        double putAt = scene.time();
        do next(); while (Math.hypot(scene.ball()[0] - s[0], scene.ball()[1] - s[1]) > 0.02 && scene.time() - putAt < 2);
        BallWatch w = new BallWatch(scene.time(), s[0], s[1], o.noTouchS(), o.afterTouchS(),
                o.attack() ? BallWatch.ATTACK_SETTLE_S : BallWatch.SETTLE_S);
        boolean down = fallen();
        String end;
        while (true) {
            next();
            boolean f = fallen();
            if (f && !down) falls++;
            down = f;
            double[] b = scene.ball();
            BallWatch.End e = w.see(scene.time(), b[0], b[1]);
            if (Math.abs(b[0]) > FIELD_X || Math.abs(b[1]) > FIELD_Y) {
                end = b[0] > FIELD_X && Math.abs(b[1]) < GOAL_HALF_WIDTH ? "goal" : "out";
                break;
            }
            if (e != BallWatch.End.RUNNING) {
                end = switch (e) {
                    case SETTLED -> "stopped";
                    case NO_TOUCH -> "untouched";
                    default -> "dribbled";
                };
                break;
            }
        }
        double toGoal = Math.toDegrees(Math.atan2(-s[1], FIELD_X - s[0]));
        double err = Double.isNaN(w.directionDeg()) ? Double.NaN : angleDiff(w.directionDeg(), toGoal);
        afterGoal = end.equals("goal");
        return new Trial(n, s[2], s[3], end, w.timeToTouch(), w.travel(), err, falls, movedFalls);
    }

    public static void main(String[] args) throws Exception {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            if (!e.getMessage().equals("help")) System.err.println("approach-bench: " + e.getMessage());
            System.err.println(USAGE);
            System.exit(e.getMessage().equals("help") ? 0 : 2);
            return;
        }
        Path root = Path.of(System.getProperty("phalanx.root", ".")).toAbsolutePath().normalize();
        if (!Files.isExecutable(root.resolve("scripts/start.sh"))) {
            System.err.println("approach-bench: no scripts/start.sh under " + root + " (run it as scripts/phalanx bench approach)");
            System.exit(2);
        }
        Path dir = o.dir() != null ? o.dir() : Files.createTempDirectory("approach-bench");
        Files.createDirectories(dir);
        int port = o.port() != 0 ? o.port() : ServerProcess.freePortPair(3700);
        double half = o.trials() * (o.noTouchS() + o.afterTouchS() + 6) + 120;
        ServerProcess server;
        try {
            // real time as well: alone, with real time off, the server runs freely until the player connects (docs/protocol.md)
            server = ServerProcess.start(new ServerProcess.Settings(port, port + 100, true, true, half, 1), dir);
        } catch (IOException e) {
            System.err.println("approach-bench: " + e.getMessage());
            System.exit(3);
            return;
        }
        SessionProcess[] player = {null};
        // Ctrl-C or kill: the server and the player are in sessions of their own and would live on
        Thread stopAll = new Thread(() -> {
            if (player[0] != null) player[0].stop("TERM", 5_000);
            server.stop();
        }, "approach-bench-stop");
        Runtime.getRuntime().addShutdownHook(stopAll);
        int status = 0;
        try (ServerConnection mon = ServerConnection.connect("127.0.0.1", port + 100, 30_000)) {
            String types = String.join(" ", java.util.Collections.nCopies(11, Integer.toString(o.type())));
            String cmd = "env PHALANX_TYPES='" + types + "' PHALANX_PLAYER_OPTS='" + o.playerOpts() + "' " + root.resolve("scripts/start.sh")
                    + " 127.0.0.1 " + port + " PhalanxBench --only " + o.unum() + " --log-dir " + dir.resolve("player");
            player[0] = SessionProcess.shell(cmd, root, dir.resolve("start.log"), "player");
            ApproachBench b = new ApproachBench(o, mon);
            long deadline = System.currentTimeMillis() + Long.getLong("approach.wait", 180) * 1000;
            while (b.torso() == null || b.scene.ball() == null) {
                if (System.currentTimeMillis() > deadline) {
                    throw new IOException(String.format(Locale.ROOT, "player %d did not appear within 180 s (monitor: %d messages, %s, ball %s, game time %.1f s); see %s",
                            o.unum(), b.scene.messages(), b.scene.hasScene() ? "a scene" : "no scene", b.scene.ball() == null ? "unseen" : "seen",
                            b.scene.time(), dir.resolve("start.log")));
                }
                b.next();
            }
            // it beams to its spot and stands (before the kick-off the game clock stands still: count pictures)
            for (int i = 0; i < 75; i++) b.next();
            mon.send("(playMode PlayOn)");
            b.pass(2);
            System.out.printf(Locale.ROOT, "approach-bench: rcssserver3d on %d, player %d type %d (%s), logs in %s%n", port, o.unum(), o.type(),
                    o.playerOpts().isEmpty() ? "default options" : o.playerOpts(), dir);
            List<Trial> done = new ArrayList<>();
            for (int n = 1; n <= o.trials(); n++) {
                Trial t = b.trial(n);
                done.add(t);
                System.out.println(t.line());
                if (!server.alive()) throw new IOException("the server exited; see " + server.log());
            }
            System.out.println(summary(done));
        } catch (IOException e) {
            System.err.println("approach-bench: " + e.getMessage());
            if (Boolean.getBoolean("approach.trace")) e.printStackTrace();
            status = 1;
        }
        System.exit(status);   // the hook stops the player and the server
    }
}

package phalanx.bench.walk;

import phalanx.motion.walk.WalkVelocity;
import phalanx.motion.walk.WalkController;
import phalanx.motion.walk.WalkConfig;
import phalanx.motion.walk.MixedCommands;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;
import phalanx.motion.MotionConfig;
import phalanx.bench.motion.BenchRig;
import phalanx.comm.monitor.MonitorScene;
import phalanx.motion.control.JointVelocities;
import phalanx.model.robot.NaoModel;

import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * scripts/phalanx bench walk: one player of each requested type in a running rcssserver3d walks with the
 * {@link WalkController}; each trial is set up with trainer commands on the monitor port and
 * measured with the monitor's scene graph (ground truth): forward speed over 10 s and 60 s,
 * turn rate in place, sideways speed, falls. With {@code --search} it tunes the named config
 * fields by coordinate descent on the forward speed instead, and prints the best config; with
 * {@code --score} it prints that search's score of the config as {@code SCORE s} (the CMA-ES walk
 * search's evaluator, {@link WalkSearch}).
 */
public final class WalkTrial {
    private static final boolean TRACE = System.getenv("WALK_TRACE") != null;
    private final WalkTrialOptions opt;
    private BenchRig rig;
    private final EffectorMessage out = new EffectorMessage();
    private Perception last;
    private int type;
    private WalkController walk;
    private long cycles;
    private double startOffset;

    private WalkTrial(WalkTrialOptions opt) { this.opt = opt; }

    public static void main(String[] args) {
        WalkTrialOptions opt;
        try {
            opt = WalkTrialOptions.parse(args);
            opt.config();
        } catch (IllegalArgumentException e) {
            System.err.println("walk-bench: " + e.getMessage());
            System.exit(2);
            return;
        }
        try {
            new WalkTrial(opt).run();
        } catch (IOException | RuntimeException e) {
            System.err.println("walk-bench: " + e);
            System.exit(1);
        }
    }

    /** What one trial measured. */
    record Result(double seconds, double forward, double left, double turnDeg, boolean fell, double fellAfter) {
        double speed() { return forward / seconds; }

        /**
         * The tuners' score of one forward trial of {@code searchSeconds} (coordinate descent and CMA-ES alike):
         * the speed; a fall scores the distance it made over the whole trial's time minus 0.2 m/s; 0.002 off
         * per degree of heading change (a curving walk is worth less).
         */
        double score(double searchSeconds) {
            double s = fell ? forward / searchSeconds - 0.2 : speed();
            return s - 0.002 * Math.abs(turnDeg);
        }
    }

    private void run() throws IOException {
        rig = BenchRig.open(opt.host(), opt.monitorPort(), "walk-bench");
        for (int t : opt.types()) {
            connect(t);
            if (opt.score()) System.out.printf(Locale.ROOT, "SCORE %s type=%d%n", score(opt.config(t)), t);
            else if (opt.search().isEmpty()) measure(opt.config(t));
            else search(opt.config(t));
            rig.disconnect();
            sleep(300); // let the server drop the player before the next one connects
        }
        rig.close();
    }

    // --- trials ---------------------------------------------------------------------------------

    private void measure(WalkConfig c) throws IOException {
        System.out.printf(Locale.ROOT, "type %d config: %s%n", type, c.describe());
        for (String s : opt.scenarios()) {
            switch (s) {
                case "forward10", "forward60" -> {
                    double secs = s.equals("forward10") ? 10 : 60;
                    for (int k = 0; k < opt.starts(); k++) {
                        startOffset = k * 0.7;
                        Result r = trial(c, new WalkVelocity(c.maxForward(), 0, 0), secs);
                        System.out.printf(Locale.ROOT, "type %d %-9s start %d request %.2f m/s: %.3f m/s over %.1f s, drift %.2f m, heading %+.0f deg, %s%n",
                                type, s, k + 1, c.maxForward(), r.speed(), r.seconds(), r.left(), r.turnDeg(), fall(r));
                    }
                    startOffset = 0;
                }
                case "turn" -> {
                    for (int dir : new int[] {1, -1}) {
                        Result r = trial(c, new WalkVelocity(0, 0, dir * c.maxTurnDeg()), opt.turnSeconds());
                        System.out.printf(Locale.ROOT, "type %d turn %-5s request %.0f deg/s: %.1f deg/s over %.1f s, moved %.2f m, %s%n",
                                type, dir > 0 ? "left" : "right", dir * c.maxTurnDeg(), r.turnDeg() / r.seconds(), r.seconds(),
                                Math.hypot(r.forward(), r.left()), fall(r));
                    }
                }
                case "side" -> {
                    for (int dir : new int[] {1, -1}) {
                        Result r = trial(c, new WalkVelocity(0, dir * c.maxLeft(), 0), opt.sideSeconds());
                        System.out.printf(Locale.ROOT, "type %d side %-5s request %.2f m/s: %.3f m/s over %.1f s, forward drift %.2f m, heading %+.0f deg, %s%n",
                                type, dir > 0 ? "left" : "right", dir * c.maxLeft(), r.left() / r.seconds(), r.seconds(), r.forward(), r.turnDeg(), fall(r));
                    }
                }
                case "mixed" -> mixed(c);
                default -> throw new IllegalStateException(s);
            }
        }
    }

    /**
     * The mixed scenario: per start one seeded {@link MixedCommands} sequence of
     * {@code --mixed-seconds}, walked from the centre spot. A fall is counted, the robot is set up
     * again where it lay (same heading, fresh walk, 1.5 s of standing not counted) and the sequence
     * goes on with its next request. Falls per minute of walking and the path covered (torso
     * positions 0.5 s apart) per start and in total.
     */
    private void mixed(WalkConfig c) throws IOException {
        int falls = 0;
        double seconds = 0, path = 0;
        for (int k = 0; k < opt.starts(); k++) {
            long seed = opt.seed() + k;
            java.util.List<MixedCommands.Segment> seq = MixedCommands.generate(seed, opt.mixedSeconds(), c);
            double heading = 90.0 * k;
            place(c, 0, 0, heading);
            if (fallen()) place(c, 0, 0, heading);
            int n = 0, fallsHere = 0;
            double len = 0;
            MonitorScene.Pose mark = torso();
            MixedCommands.Segment before = null;
            for (MixedCommands.Segment s : seq) {
                int cyclesHere = (int) Math.round(s.seconds() / 0.02);
                for (int i = 0; i < cyclesHere; i++) {
                    cycle(s.request());
                    n++;
                    if (n % 25 == 0) {
                        MonitorScene.Pose p = torso();
                        len += Math.hypot(p.x() - mark.x(), p.y() - mark.y());
                        mark = p;
                    }
                    if (fallen()) {
                        fallsHere++;
                        MonitorScene.Pose p = torso();
                        len += Math.hypot(p.x() - mark.x(), p.y() - mark.y());
                        System.out.printf(Locale.ROOT, "type %d mixed seed %d: FELL at %.2f s, %.2f s into %s after %s; walk at (%.2f, %.2f, %.0f)%n",
                                type, seed, n * 0.02, i * 0.02, s, before, walk.velocity().forward(), walk.velocity().left(), walk.velocity().turnDeg());
                        double x = Math.max(-20, Math.min(20, p.x())), y = Math.max(-20, Math.min(20, p.y()));
                        place(c, x, y, p.yawDeg());
                        if (fallen()) place(c, x, y, p.yawDeg());
                        mark = torso();
                        break;
                    }
                    MonitorScene.Pose p = torso();
                    if (Math.abs(p.x()) > 22 || Math.abs(p.y()) > 22) {   // near the walls: back to the centre, same heading
                        len += Math.hypot(p.x() - mark.x(), p.y() - mark.y());
                        place(c, 0, 0, p.yawDeg());
                        mark = torso();
                    }
                }
                before = s;
            }
            double secs = n * 0.02;
            System.out.printf(Locale.ROOT, "type %d mixed    start %d seed %d: %d falls in %.1f s (%.2f /min), path %.1f m (%.2f m/s), %d requests%n",
                    type, k + 1, seed, fallsHere, secs, fallsHere * 60 / secs, len, len / secs, seq.size());
            falls += fallsHere;
            seconds += secs;
            path += len;
        }
        System.out.printf(Locale.ROOT, "type %d mixed    total seeds %d-%d: %d falls in %.1f s = %.2f falls/min, path %.1f m (%.2f m/s)%n",
                type, opt.seed(), opt.seed() + opt.starts() - 1, falls, seconds, falls * 60 / seconds, path, path / seconds);
    }

    private static String fall(Result r) {
        return r.fell() ? String.format(Locale.ROOT, "FELL after %.1f s", r.fellAfter()) : "no fall";
    }

    /** Objective of both searches (--search, and --score for the CMA-ES one): the worst trial's {@link Result#score}. */
    private double score(WalkConfig c) throws IOException {
        double worst = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 2; k++) { // two starts a little apart: the worst counts (the server is deterministic)
            startOffset = k * 0.7;
            Result r = trial(c, new WalkVelocity(c.maxForward(), 0, 0), opt.searchSeconds());
            double s = r.score(opt.searchSeconds());
            System.out.printf(Locale.ROOT, "  score %.3f  (%.3f m/s, heading %+.0f deg, %s)%n", s, r.speed(), r.turnDeg(), fall(r));
            worst = Math.min(worst, s);
            if (r.fell()) break;
        }
        startOffset = 0;
        return worst;
    }

    private void search(WalkConfig start) throws IOException {
        Map<String, Double> steps = new LinkedHashMap<>(opt.search());
        WalkConfig best = start;
        System.out.printf(Locale.ROOT, "type %d search from: %s%n", type, best.describe());
        double bestScore = score(best);
        for (int round = 0; round < opt.rounds(); round++) {
            for (Map.Entry<String, Double> e : steps.entrySet()) {
                String f = e.getKey();
                double step = e.getValue();
                for (int dir : new int[] {1, -1}) {
                    boolean improved = true;
                    while (improved) {
                        improved = false;
                        WalkConfig cand;
                        try {
                            cand = best.with(f, best.get(f) + dir * step);
                        } catch (IllegalArgumentException ex) {
                            break; // out of range
                        }
                        System.out.printf(Locale.ROOT, "round %d %s=%.4f%n", round + 1, f, cand.get(f));
                        double s = score(cand);
                        if (s > bestScore + 0.005) {
                            best = cand;
                            bestScore = s;
                            improved = true;
                            System.out.printf(Locale.ROOT, "  best now %.3f: %s=%.4f%n", bestScore, f, best.get(f));
                        }
                    }
                }
            }
            steps.replaceAll((k, v) -> v / 2);
        }
        System.out.printf(Locale.ROOT, "type %d best score %.3f: %s%n", type, bestScore, best.describe());
        StringBuilder set = new StringBuilder();
        for (String f : WalkConfig.FIELDS) if (best.get(f) != WalkConfig.forType(type).get(f)) set.append(set.length() == 0 ? "" : ",").append(f).append('=').append(best.get(f));
        System.out.println("--set " + set);
    }

    /**
     * Places the robot, lets it stand, then walks with the request for {@code seconds} after one
     * second of start-up (not measured). Distances in the start heading's frame.
     */
    private Result trial(WalkConfig c, WalkVelocity request, double seconds) throws IOException {
        double[] start = request.turnDeg() != 0 ? new double[] {-5, 12, 0} : request.left() != 0 ? new double[] {0, -18, 0}
                : new double[] {-22 + startOffset, -22, 45 + 5 * startOffset};
        for (int attempt = 0; ; attempt++) {
            place(c, start[0], start[1], start[2]);
            if (!fallen()) break;
            if (attempt == 3) throw new IOException("the robot does not stand after being placed (type " + type + ")");
        }
        for (int i = 0; i < 50; i++) cycle(request); // start-up
        MonitorScene.Pose a = torso();
        double t0 = clock(), prevYaw = a.yawDeg(), turned = 0;
        int n = (int) Math.round(seconds / 0.02);
        boolean fell = false;
        double fellAfter = Double.NaN;
        for (int i = 0; i < n; i++) {
            cycle(request);
            MonitorScene.Pose p = torso();
            double d = p.yawDeg() - prevYaw;
            while (d > 180) d -= 360;
            while (d < -180) d += 360;
            turned += d;
            prevYaw = p.yawDeg();
            if (TRACE) System.err.printf(Locale.ROOT, "trace est pitch %.1f roll %.1f mon %d cyc %d %.2f pos %.3f %.3f z %.3f yaw %.1f pitch(fwdZ) %+.3f roll(rightZ) %+.3f gyro %s acc %s feet %s%n",
                    walk.pitchForward(), walk.rollRight(), monitorMessages(), cycles, clock() - t0, p.x(), p.y(), p.z(), p.yawDeg(), p.forwardZ(), p.r()[6], last.gyro(), last.acc(), last.footForces());
            if (fallen()) {
                fell = true;
                fellAfter = clock() - t0;
                break;
            }
        }
        MonitorScene.Pose b = torso();
        double dt = clock() - t0, h = Math.toRadians(a.yawDeg());
        double dx = b.x() - a.x(), dy = b.y() - a.y();
        double fwd = dx * Math.cos(h) + dy * Math.sin(h), left = -dx * Math.sin(h) + dy * Math.cos(h);
        return new Result(dt, fwd, left, turned, fell, fellAfter);
    }

    /** Trainer move to (x, y) facing {@code headingDeg} (0 = +x), fresh walk, 1.5 s of standing. */
    private void place(WalkConfig c, double x, double y, double headingDeg) throws IOException {
        trainer("(ball (pos 20 -20 0.042))");
        NaoModel g = NaoModel.ofType(type);
        double z = g.ankleAboveSole() + c.legExtension() * (g.thigh() + g.shank()) + g.hipBelowTorso() + 0.03;
        // the move's angle 0 faces +y (recordings README)
        trainer(String.format(Locale.ROOT, "(agent (unum 1) (team Left) (move %.3f %.3f %.3f %.1f))", x, y, z, headingDeg - 90));
        walk = new WalkController(c, type, MotionConfig.DEFAULT);
        for (int i = 0; i < 75; i++) cycle(WalkVelocity.ZERO);
    }

    private boolean fallen() {
        MonitorScene.Pose p = torso();
        double standing = NaoModel.ofType(type).standingTorsoHeight();
        return p != null && (p.upZ() < 0.5 || p.z() < 0.5 * standing);
    }

    // --- wire -----------------------------------------------------------------------------------

    private void connect(int t) throws IOException {
        type = t;
        rig.connect(opt.host(), opt.port(), t);
        last = rig.last();
        walk = new WalkController(WalkConfig.forType(t), t, MotionConfig.DEFAULT);
        for (int i = 0; i < 25; i++) cycle(WalkVelocity.ZERO);
        trainer("(playMode PlayOn)");
        for (int i = 0; i < 10; i++) cycle(WalkVelocity.ZERO);
        if (torso() == null) throw new IOException("the monitor shows no player 1 of team Left (is another team on the left?)");
    }

    private void cycle(WalkVelocity request) throws IOException {
        last = rig.receive();
        cycles++;
        JointVelocities v = walk.step(last.joints(), last.gyro(), last.acc(), request);
        out.reset();
        v.appendTo(out).syn();
        rig.send(out.text());
    }

    private void trainer(String command) throws IOException { rig.trainer(command); }

    /**
     * Simulated seconds, counted in cycles of 0.02 s: the server's {@code now} is a float32 that,
     * after a long free run (tens of thousands of seconds), advances by 0.0195 or 0.0234 per cycle.
     */
    private double clock() { return cycles * 0.02; }

    private int monitorMessages() { return rig.scene(MonitorScene::messages); }

    private MonitorScene.Pose torso() { return rig.torso(); }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

package phalanx.bench.motion;

import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionFileException;
import phalanx.motion.MotionLibrary;
import phalanx.motion.control.JointVelocities;
import phalanx.motion.control.MotionController;
import phalanx.motion.control.MotionRequest;
import phalanx.model.robot.NaoModel;
import phalanx.motion.walk.WalkConfig;
import phalanx.motion.walk.WalkController;
import phalanx.motion.walk.WalkVelocity;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * scripts/motion-bench: one player in a running rcssserver3d, trials set up with the monitor port's
 * trainer commands and measured with the monitor's scene graph (ground truth): forward walk speed,
 * turn rate, kick distance and direction error, get-up success and time, falls, per robot type.
 * Prints a table; the last line is the summary (means over the types). A trial the server did not set up
 * as asked (the robot not where it was moved, the ball not placed, no picture, a robot or ball that never
 * moved: {@link TrialCheck}) adds no figure; each says why on stderr, the tables count them, and the bench
 * exits with status 3 when a figure got no measured trial (1 when it cannot run at all, 2 for a bad flag).
 */
public final class MotionBench {
    private final BenchOptions opt;
    private final Map<Integer, MotionLibrary> libraries; // per robot type (motions/typeN/ files replace the folder's)
    private MotionLibrary library;
    private BenchRig rig;

    // the player of the type being measured
    private MotionController controller;
    private final EffectorMessage out = new EffectorMessage();
    private Perception last;
    private double standingZ;
    private long cycles;

    private MotionBench(BenchOptions opt, Map<Integer, MotionLibrary> libraries) {
        this.opt = opt;
        this.libraries = libraries;
    }

    public static void main(String[] args) {
        BenchOptions opt;
        Map<Integer, MotionLibrary> lib = new HashMap<>();
        try {
            opt = BenchOptions.parse(args);
            for (int type : opt.types()) lib.put(type, MotionLibrary.load(opt.motions(), type));
        } catch (IllegalArgumentException | MotionFileException e) {
            System.err.println("motion-bench: " + e.getMessage());
            System.exit(2);
            return;
        }
        boolean measured;
        try {
            measured = new MotionBench(opt, lib).run();
        } catch (IOException | RuntimeException e) {
            System.err.println("motion-bench: " + e.getMessage());
            System.exit(1);
            return;
        }
        if (!measured) System.exit(3);
    }

    /** Per-type results. */
    static final class Row {
        int type;
        List<Double> walk = new ArrayList<>(), turnL = new ArrayList<>(), turnR = new ArrayList<>();
        List<Double> kick = new ArrayList<>(), kickDir = new ArrayList<>(), strong = new ArrayList<>(), strongDir = new ArrayList<>();
        /** Get-ups of one direction (the motion played). */
        static final class Getups {
            int tries, ok, walks, walkFalls;
            List<Double> time = new ArrayList<>();
        }
        final Getups front = new Getups(), back = new Getups();
        int falls;
        double walkMinutes;
        final java.util.Map<String, KickStats> kicks = new java.util.LinkedHashMap<>();
        final java.util.Map<String, DiveStats> dives = new java.util.LinkedHashMap<>();
        /** Per figure (walk, turn_left, a kick or dive motion, getup): trials that measured and that did not, with why. */
        final Tally tally = new Tally();
    }

    /** One kick motion's trials on one type: {@code tries} of them, the measured ones in the lists. */
    static final class KickStats {
        final List<Double> distance = new ArrayList<>(), dirError = new ArrayList<>();
        int falls, tries;
    }

    /** One dive motion's trials on one type. */
    static final class DiveStats {
        final List<Double> downSeconds = new ArrayList<>(), reach = new ArrayList<>(), reachSeconds = new ArrayList<>();
        int stopped, shots;
    }

    /** False when a figure asked for got no measured trial (the reasons are printed). */
    private boolean run() throws IOException {
        rig = BenchRig.open(opt.host(), opt.monitorPort(), "motion-bench");
        String noScene = rig.awaitScene(10_000);
        if (noScene != null) {
            rig.close();
            throw new IOException("no scene from the monitor port " + opt.monitorPort() + ": " + noScene
                    + " (is it the --server-port of a running rcssserver3d? a server whose monitor port was taken starts without one)");
        }
        // no (playMode PlayOn) yet: a server with real time off and no player would run the game clock on to
        // half time and game over before our player joins; each trial starts play itself (place)
        List<Row> rows = new ArrayList<>();
        for (int type : opt.types()) rows.add(measure(type));
        System.err.println("motion-bench: " + rig.lagReport());
        rig.close();
        print(rows);
        return everyFigureMeasured(rows);
    }

    private void trainer(String command) throws IOException { rig.trainer(command); }

    private MonitorScene.Pose torso() { return rig.torso(); }

    private double[] ball() { return rig.ball(); }

    /**
     * The ball's place in the latest monitor picture, timed by the picture's game time rounded to whole
     * cycles ({@link #pictureSeconds}). The server's own float clock stops advancing in a server that ran
     * freely between bench runs (docs/protocol.md), and counting pictures as cycles doubled every launch
     * speed on a server with the installed {@code $monitorStep = 0.04} (a picture every other cycle).
     */
    private void sample(BallLaunch launch) {
        double[] tb = rig.scene(s -> { double[] b = s.ball(); return b == null ? null : new double[] {pictureSeconds(s.time(), s.messages()), b[0], b[1], b[2]}; });
        if (tb != null) launch.add(tb[0], tb[1], tb[2], tb[3]);
    }

    /**
     * A picture's time for launch speeds: its game time (the bench resets it to 0 before each trial, so it
     * is exact) rounded to a whole 0.02 s cycle; without one, the picture's number at one picture a cycle.
     */
    static double pictureSeconds(double gameTime, int pictureNumber) {
        return Double.isNaN(gameTime) ? pictureNumber * 0.02 : Math.round(gameTime / 0.02) * 0.02;
    }

    // --- the player -----------------------------------------------------------------------------

    private Row measure(int type) throws IOException {
        Row row = new Row();
        row.type = type;
        standingZ = NaoModel.ofType(type).standingTorsoHeight();
        connect(type);
        for (int t = 0; t < opt.trials(); t++) {
            if (opt.runs("walk")) walk(row);
            if (opt.runs("turn")) {
                double l = turn(row, "turn_left"), r = turn(row, "turn_right");
                if (!Double.isNaN(l)) row.turnL.add(l);
                if (!Double.isNaN(r)) row.turnR.add(-r);
            }
            if (opt.runs("kick")) kicks(row);
            if (opt.runs("dive")) dives(row);
            if (opt.runs("getup")) {
                for (int k = 0; k < 4; k++) if (opt.lying().contains(List.of("front", "back", "side", "oblique").get(k))) getUp(row, lying(t, k), 0);
            }
            System.err.printf(Locale.ROOT, "type %d trial %d done (%d cycles)%n", type, t + 1, cycles);
        }
        rig.disconnect();
        hold0(50); // let the server drop the player before the next type connects
        return row;
    }

    private int connectedType;

    private void connect(int type) throws IOException {
        connectedType = type;
        library = libraries.get(type);
        rig.connect(opt.host(), opt.port(), type);
        last = rig.last();
        controller = new MotionController(library, MotionConfig.DEFAULT);
        hold(25);
        String joined = rig.joinedAsPlayer1Left();
        if (joined != null) throw new IOException(joined);
        String unsynced = rig.syncModeProblem();
        if (unsynced != null) throw new IOException(unsynced);
        last = rig.last();
        cycles++;
        rig.send("(syn)"); // the answer to the message the check read
        rig.trackLag();
        trainer("(playMode PlayOn)");
    }

    /**
     * Set when a message shows the referee out of PlayOn. The bench's server keeps its 300 s halves: at
     * half time the referee puts the ball on the centre spot and keeps it there, and moves robots out of
     * the opponents' half, and after the second half the game is over (session 6: a type 2 run after
     * type 0 "kicked" 0.00 m ten times). Each trial starts at game time 0 in PlayOn ({@link #place});
     * a kick or get-up during which play still stopped is void and measured again.
     */
    private boolean playStopped;

    private void receive() throws IOException {
        last = rig.receive();
        PlayMode pm = last.gameState() == null ? PlayMode.UNKNOWN : last.gameState().playMode();
        if (pm != PlayMode.PLAY_ON && pm != PlayMode.UNKNOWN) playStopped = true; // UNKNOWN: no pm in the message
    }

    /** True (with a line saying so) when the referee stopped play during the trial just measured. */
    private boolean voided(String what) {
        if (!playStopped) return false;
        System.err.printf(Locale.ROOT, "  %s: void, the referee stopped play during the trial (half time?); measured again%n", what);
        return true;
    }

    /** One cycle: read, step the controller, reply. A small head motion keeps trainer-moved robots from hanging. */
    private void cycle(MotionRequest request) throws IOException {
        receive();
        cycles++;
        // the bench's own cycle clock, not the server's float time: in a server that ran freely it advances
        // in steps of 1/64 s and would stretch or shorten every phase by up to 20 %
        JointVelocities v = controller.step(simTime(), last.joints(), last.acc(), request);
        v = v.with(Joint.HJ1, 0.2 * Math.sin(cycles * 0.2));
        out.reset();
        v.appendTo(out).syn();
        rig.send(out.text());
        if (opt.trace() && cycles % 5 == 0) {
            MonitorScene.Pose p = torso();
            double[] b = ball();
            if (p != null) System.err.printf(Locale.ROOT, "  t=%.2f %s/%s pos=(%.3f %.3f %.3f) yaw=%.1f up=%.2f fwdZ=%.2f accFwd=%.2f ball=(%.2f %.2f) legs L %.0f/%.0f/%.0f R %.0f/%.0f/%.0f%n", last.time(),
                    controller.playingMotion(), controller.segment(), p.x(), p.y(), p.z(), p.yawDeg(), p.upZ(), p.forwardZ(),
                    phalanx.motion.phase.Check.Axis.FORWARD.share(last.acc()), b == null ? 0 : b[0], b == null ? 0 : b[1],
                    last.joints().degrees(Joint.LLJ3), last.joints().degrees(Joint.LLJ4), last.joints().degrees(Joint.LLJ5),
                    last.joints().degrees(Joint.RLJ3), last.joints().degrees(Joint.RLJ4), last.joints().degrees(Joint.RLJ5));
        }
    }

    /**
     * {@code --trace} during a kick, every cycle: the phase, both legs' six joints (yaw-pitch, roll, pitch,
     * knee, ankle pitch, ankle roll; degrees as perceived) and the ball, to read joint speeds at contact.
     */
    private void traceKick() {
        double[] b = ball();
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "  kick c=%d %s ball=(%.3f %.3f %.3f)", cycles, controller.segment(),
                b == null ? 0 : b[0], b == null ? 0 : b[1], b == null ? 0 : b[2]));
        for (Joint first : new Joint[] {Joint.LLJ1, Joint.RLJ1}) {
            sb.append(first == Joint.LLJ1 ? " L" : " R");
            for (int j = 0; j < 6; j++) sb.append(String.format(Locale.ROOT, " %.1f", last.joints().degrees(Joint.byIndex(first.ordinal() + j))));
        }
        System.err.println(sb);
    }

    /**
     * Simulated seconds from our own cycle count (the server runs in sync mode, so no cycle is lost),
     * not from its float clock, which gets coarse in a server that has run long without agents.
     */
    private double simTime() { return cycles * 0.02; }

    private void hold(int n) throws IOException { for (int i = 0; i < n; i++) cycle(MotionRequest.NONE); }

    private void hold0(int n) {
        try {
            Thread.sleep(n * 20L);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Trainer move to (x, y) facing +x (the move's angle 0 faces +y, recordings README), then let it
     * stand. The joints are first brought to the walk's start pose wherever the robot is (a move
     * resets position and orientation, not the joints), so every trial starts alike. Null when the robot
     * stands where it was moved, in PlayOn from game time 0, else why not ({@link TrialCheck#placement}):
     * then the trial measures nothing.
     */
    private String place(double x, double y) throws IOException {
        controller = new MotionController(library, MotionConfig.DEFAULT); // drop whatever was playing
        onceStarted = false;
        double[] ready = readyPose();
        for (int i = 0; i < 40; i++) {
            receive();
            out.reset();
            for (Joint j : Joint.values()) {
                if (!last.joints().has(j)) continue;
                double target = Double.isNaN(ready[j.ordinal()]) ? 0 : ready[j.ordinal()];
                out.hinge(j, Math.max(-6, Math.min(6, Math.toRadians(target - last.joints().degrees(j)) * 10)));
            }
            rig.send(out.syn().text());
        }
        trainer(String.format(Locale.ROOT, "(agent (unum 1) (team Left) (move %.3f %.3f %.3f -90))", x, y, standingZ - 0.02));
        // game time back to 0 and play on: no trial runs into the half's end (300 s on a standard server)
        trainer("(time 0)");
        trainer("(playMode PlayOn)");
        int pictures = rig.pictures();
        hold(50);
        playStopped = false;
        MonitorScene.Pose p = torso();
        PlayMode pm = last.gameState() == null ? null : last.gameState().playMode();
        double gameTime = last.gameState() == null ? Double.NaN : last.gameState().gameTime();
        return TrialCheck.placement(p == null ? Double.NaN : Math.hypot(p.x() - x, p.y() - y), gameTime, pm, rig.pictures() - pictures,
                rig.pictureTime() - gameTime);
    }

    /** A trial that measured nothing: one line saying why, counted for its figure. */
    private static void notMeasured(Row row, String figure, String why) {
        row.tally.unmeasured(figure, why);
        System.err.printf(Locale.ROOT, "  %s: not measured: %s%n", figure, why);
    }

    /** The first phase of walk_forward: the crouch every motion starts from. */
    private double[] readyPose() {
        double[] t = new double[Joint.COUNT];
        java.util.Arrays.fill(t, Double.NaN);
        if (library.get("walk_forward") instanceof phalanx.motion.phase.PhaseMotion pm) {
            phalanx.motion.phase.Phase p = pm.phase(pm.first());
            for (Joint j : Joint.values()) t[j.ordinal()] = p.targetDeg(j);
        }
        return t;
    }

    private boolean fallen() {
        MonitorScene.Pose p = torso();
        return p != null && (p.upZ() < 0.5 || p.z() < 0.5 * standingZ);
    }

    private void walk(Row row) throws IOException {
        String unplaced = place(-8, 0);
        if (unplaced != null) {
            notMeasured(row, "walk", unplaced);
            return;
        }
        int n = (int) Math.round(opt.walkSeconds() / 0.02);
        MotionRequest walk = MotionRequest.of("walk_forward");
        for (int i = 0; i < 50; i++) cycle(walk); // start-up, not measured
        MonitorScene.Pose a = torso();
        double t0 = simTime();
        int pictures = rig.pictures();
        boolean fell = false;
        for (int i = 0; i < n && !fell; i++) {
            cycle(walk);
            fell = fallen();
        }
        MonitorScene.Pose b = torso();
        double dt = simTime() - t0;
        String still = TrialCheck.motion(rig.pictures() - pictures, Math.hypot(b.x() - a.x(), b.y() - a.y()));
        if (still != null) {
            notMeasured(row, "walk", still);
            return;
        }
        double heading = Math.toRadians(a.yawDeg());
        double along = (b.x() - a.x()) * Math.cos(heading) + (b.y() - a.y()) * Math.sin(heading);
        row.tally.measured("walk");
        row.walk.add(along / dt);
        row.walkMinutes += dt / 60;
        if (fell) row.falls++;
        for (int i = 0; i < 100 && controller.playing() != null && !fell; i++) cycle(MotionRequest.NONE);
    }

    /** Degrees per second, counter-clockwise positive; NaN when the trial measured nothing (said why). */
    private double turn(Row row, String motion) throws IOException {
        String unplaced = place(-4, 4);
        if (unplaced != null) {
            notMeasured(row, motion, unplaced);
            return Double.NaN;
        }
        MotionRequest r = MotionRequest.of(motion);
        for (int i = 0; i < 10; i++) cycle(r);
        MonitorScene.Pose start = torso();
        double yaw0 = start.yawDeg(), prev = yaw0, total = 0;
        double t0 = simTime();
        int pictures = rig.pictures();
        int n = (int) Math.round(opt.turnSeconds() / 0.02);
        for (int i = 0; i < n && !fallen(); i++) {
            cycle(r);
            double y = torso().yawDeg();
            double d = y - prev;
            while (d > 180) d -= 360;
            while (d < -180) d += 360;
            total += d;
            prev = y;
        }
        double rate = total / (simTime() - t0);
        MonitorScene.Pose end = torso();
        double moved = Math.max(Math.abs(Math.toRadians(total)), Math.hypot(Math.hypot(end.x() - start.x(), end.y() - start.y()), end.z() - start.z()));
        String still = TrialCheck.motion(rig.pictures() - pictures, moved);
        if (still != null) {
            notMeasured(row, motion, still);
            return Double.NaN;
        }
        row.tally.measured(motion);
        boolean fell = fallen();
        System.err.printf(Locale.ROOT, "  %s: %.1f deg/s%s%n", motion, rate, fell ? ", fell (counted as 0)" : "");
        if (fell) getUpQuietly();
        return fell ? 0 : rate; // turning while falling over is no turn
    }

    /**
     * The request that plays a one-shot motion once: the motion until it shows as playing, then
     * nothing (the controller restarts a one-shot motion still requested when it ends, and one
     * without a finalize phase then plays twice; the agent's OneShot does the same).
     */
    private MotionRequest onceRequest(String motion, boolean interrupting) {
        if (motion.equals(controller.playing())) onceStarted = true;
        if (onceStarted) return MotionRequest.NONE;
        MotionRequest r = MotionRequest.of(motion);
        return interrupting ? r.interrupting() : r;
    }

    private boolean onceStarted;

    /**
     * Every kick of {@code --kicks} once; "kick" and "strong_kick" also fill the summary columns. A kick
     * that measured nothing ({@link TrialCheck#kick}) adds no figure: its reason is printed and counted.
     */
    private void kicks(Row row) throws IOException {
        for (String motion : opt.kicks()) {
            KickStats st = row.kicks.computeIfAbsent(motion, m -> new KickStats());
            Kick k = kick(motion);
            for (int again = 0; again < 3 && voided(motion); again++) k = kick(motion);
            if (playStopped) k = Kick.none("the referee stopped play in each of 4 tries (half time or game over?)");
            st.tries++;
            if (k.unmeasured() != null) {
                notMeasured(row, motion, k.unmeasured());
                continue;
            }
            row.tally.measured(motion);
            st.distance.add(k.distance());
            st.dirError.add(k.dirError());
            if (k.fell()) st.falls++;
            if (motion.equals("kick")) { row.kick.add(k.distance()); row.kickDir.add(k.dirError()); }
            if (motion.equals("strong_kick")) { row.strong.add(k.distance()); row.strongDir.add(k.dirError()); }
        }
    }

    /** One kick: what it measured, or (every figure NaN) why it measured nothing. */
    record Kick(double distance, double dirError, boolean fell, String unmeasured) {
        static Kick none(String why) { return new Kick(Double.NaN, Double.NaN, false, why); }
    }

    /**
     * One kick from a standing start: the distance, the direction error (deg) and whether the robot fell.
     * The ball lies {@code --ball-ahead} ahead of the torso and {@code --ball-side} to the side of the
     * kicking foot (right, or left for a motion named *_left). A fall anywhere from the start of the
     * kick until the ball stops (at least 1 s after the motion ended) counts. Measures nothing, with the
     * reason, when the robot was not where it was moved, the ball not where it was put, no picture came,
     * the robot in the picture never moved, or the ball never moved.
     */
    private Kick kick(String motion) throws IOException {
        String unplaced = place(0, -3);
        if (unplaced != null) return Kick.none(unplaced);
        MonitorScene.Pose p = torso();
        double h = Math.toRadians(p.yawDeg());
        double side = motion.endsWith("_left") ? -opt.ballSide() : opt.ballSide(); // to the right of the torso
        double ahead = opt.ballAhead() + opt.ballJitter() * (2 * kickJitter.nextDouble() - 1);
        side += opt.ballJitter() * (2 * kickJitter.nextDouble() - 1);
        double bx = p.x() + ahead * Math.cos(h) + side * Math.sin(h), by = p.y() + ahead * Math.sin(h) - side * Math.cos(h);
        // (vel 0 0 0): a move keeps the ball's velocity, and the last kick's ball, still rolling at up to
        // 1 cm/s when the bench took it as stopped, crept 1-2 cm off the spot before the next swing
        trainer(String.format(Locale.ROOT, "(ball (pos %.3f %.3f 0.042) (vel 0 0 0))", bx, by));
        hold(10);
        for (int i = 0; i < 100 && ballOff(bx, by) > 0.01; i++) hold(1); // settling
        double[] b0 = ball();
        double ballOffSpot = ballOff(bx, by);
        if (b0 == null) return Kick.none("no ball in the monitor's scene");
        int pictures = rig.pictures();
        KickWatch watch = new KickWatch(rig.scene(s -> s.parts(1, "Left")), b0);
        long done = controller.completions();
        boolean fell = false;
        BallLaunch launch = new BallLaunch();
        for (int i = 0; i < 250 && controller.completions() == done; i++) {
            cycle(onceRequest(motion, false));
            fell |= fallen();
            sample(launch);
            watch.see(rig.scene(s -> s.parts(1, "Left")), ball());
            if (opt.trace()) traceKick();
        }
        for (int i = 0; i < 25; i++) { // the ball's first half second after the motion, for its launch speed
            hold(1);
            sample(launch);
            watch.see(rig.scene(s -> s.parts(1, "Left")), ball());
        }
        double[] prev = ball();
        for (int i = 0; i < 400; i++) { // until the ball stops (at most 8 s), the robot standing at least 1 s
            hold(10);
            fell |= fallen();
            double[] b = ball();
            watch.see(null, b);
            if (i >= 5 && Math.hypot(b[0] - prev[0], b[1] - prev[1]) < 0.002) break;
            prev = b;
        }
        double[] b1 = ball();
        double dx = b1[0] - b0[0], dy = b1[1] - b0[1];
        double dist = Math.hypot(dx, dy);
        double err = dist < 0.05 ? Double.NaN : Math.toDegrees(Math.atan2(Math.sin(Math.atan2(dy, dx) - h), Math.cos(Math.atan2(dy, dx) - h)));
        String why = TrialCheck.kick(ballOffSpot, rig.pictures() - pictures, watch.bodyTravel(), watch.closest(), watch.ballTravel());
        if (why == null) {
            System.err.printf(Locale.ROOT, "  %s: %.2f m, direction error %.1f deg%s, launch %.2f m/s, up %.2f m/s, nearest part %.3f m%n",
                    motion, dist, err, fell ? ", fell" : "", launch.speed(), launch.up(), watch.closest());
        }
        // A robot moved upright by the trainer straight from lying on its face fell in the next kick before
        // reaching the ball (3 of 3 such trials); getting up first, as a player would, starts the next trial alike.
        if (fell) getUpQuietly();
        return why != null ? Kick.none(why) : new Kick(dist, Math.abs(err), fell, null);
    }

    /** The ball's distance from (x, y) in the latest picture, NaN without a ball. */
    private double ballOff(double x, double y) {
        double[] b = ball();
        return b == null ? Double.NaN : Math.hypot(b[0] - x, b[1] - y);
    }

    /**
     * The agent's choice (localization FallDetector with LocalizationConfig.fallBackMinDeg = 30): the back
     * get-up only when the chest faces more than 30 degrees up; on a side, the front one.
     */
    static boolean lyingOnBack(MonitorScene.Pose p) { return p.forwardZ() > Math.sin(Math.toRadians(30)); }

    private void getUpQuietly() throws IOException {
        for (int tries = 0; tries < 3 && fallen(); tries++) {
            MonitorScene.Pose p = torso();
            String m = lyingOnBack(p) ? "stand_up_back" : "stand_up_front";
            long done = controller.completions();
            for (int i = 0; i < 300 && controller.completions() == done; i++) cycle(MotionRequest.of(m).interrupting());
            hold(50);
        }
    }

    /**
     * The lying positions a get-up trial starts from: tipped over by the ankles in a direction
     * (0° forward, 180° backward, ±90° onto a side, the obliques in between), with the arms and legs
     * held in a random pose while falling, as after a walk step, a kick or a collision.
     */
    enum Lying {
        FRONT(0), BACK(180), LEFT(90), RIGHT(-90), FRONT_LEFT(35), FRONT_RIGHT(-35), BACK_LEFT(145), BACK_RIGHT(-145);
        final double deg;
        Lying(double deg) { this.deg = deg; }
    }

    /** Trial i of a type: front, back, a side, an oblique, in turn. */
    static Lying lying(int trial, int k) {
        return switch (k) {
            case 0 -> Lying.FRONT;
            case 1 -> Lying.BACK;
            case 2 -> trial % 2 == 0 ? Lying.LEFT : Lying.RIGHT;
            default -> List.of(Lying.FRONT_LEFT, Lying.BACK_RIGHT, Lying.FRONT_RIGHT, Lying.BACK_LEFT).get(trial % 4);
        };
    }

    private final java.util.Random random = new java.util.Random(6);
    private final java.util.Random kickJitter = new java.util.Random(7); // its own: get-up trials stay as they were

    /**
     * Tips the robot over (ankle pitch for forward/backward as in recording S3, ankle and hip roll
     * sideways), lets it lie still, then requests the get-up the agent would choose (from the sign
     * of the torso's forward axis, as FallDetector does with the accelerometer). Success: upright
     * (not fallen by the walk's test) 1 s after the motion ended; time: from the request until the
     * torso is upright at 3/4 of standing height. With --getup-walk the walk then starts at full speed.
     */
    private void getUp(Row row, Lying lying, int again) throws IOException {
        String unplaced = place(4, 4);
        if (unplaced != null) {
            notMeasured(row, "getup", unplaced);
            return;
        }
        if (fallen()) {
            // seen twice in long runs: the robot kept lying on its back after every trainer move (its
            // body stuck in the server); a new player is the only way out, and the trial starts afresh
            System.err.printf(Locale.ROOT, "  the robot does not stand after a trainer move: reconnecting it%n");
            rig.disconnect();
            hold0(50);
            connect(connectedType);
            place(4, 4);
            if (fallen()) throw new IOException("the robot does not stand after a trainer move, even as a new player");
        }
        double[] pose = new double[Joint.COUNT];          // random limbs, held during the fall
        java.util.Arrays.fill(pose, Double.NaN);
        double sh = -120 + 160 * random.nextDouble(), hip = -10 + 50 * random.nextDouble(), knee = -70 * random.nextDouble();
        pose[Joint.LAJ1.ordinal()] = sh + 20 * random.nextGaussian();
        pose[Joint.RAJ1.ordinal()] = sh + 20 * random.nextGaussian();
        pose[Joint.LAJ2.ordinal()] = 40 * random.nextDouble();
        pose[Joint.RAJ2.ordinal()] = -40 * random.nextDouble();
        pose[Joint.LLJ3.ordinal()] = hip;
        pose[Joint.RLJ3.ordinal()] = hip + 10 * random.nextGaussian();
        pose[Joint.LLJ4.ordinal()] = knee;
        pose[Joint.RLJ4.ordinal()] = knee + 10 * random.nextGaussian();
        double a = Math.toRadians(lying.deg + 10 * random.nextGaussian());
        double pitch = 2 * Math.cos(a), roll = 2 * Math.sin(a);
        for (int i = 0; i < 150 && !fallen(); i++) {
            receive();
            out.reset();
            for (Joint j : Joint.values()) {
                if (!last.joints().has(j) || Double.isNaN(pose[j.ordinal()])) continue;
                out.hinge(j, Math.max(-6, Math.min(6, Math.toRadians(pose[j.ordinal()] - last.joints().degrees(j)) * 5)));
            }
            // + ankle pitch tips forward; + ankle/hip roll moves the legs left, the torso tips right
            out.hinge(Joint.LLJ5, pitch).hinge(Joint.RLJ5, pitch)
               .hinge(Joint.LLJ6, -roll).hinge(Joint.RLJ6, -roll).hinge(Joint.LLJ2, -roll).hinge(Joint.RLJ2, -roll);
            rig.send(out.syn().text());
        }
        hold(50 + random.nextInt(75)); // lie still 1-2.5 s
        if (!fallen()) {
            System.err.printf(Locale.ROOT, "  getup %s: did not fall, no trial%n", lying);
            return;
        }
        MonitorScene.Pose p = torso();
        boolean front = !lyingOnBack(p);
        Row.Getups g = front ? row.front : row.back;
        String motion = front ? "stand_up_front" : "stand_up_back";
        g.tries++;
        double t0 = simTime();
        double upAt = Double.NaN;
        long done = controller.completions();
        MotionRequest r = MotionRequest.of(motion).interrupting();
        double best = 0;
        for (int i = 0; i < 400 && controller.completions() == done; i++) {
            cycle(r);
            best = Math.max(best, torso().z() * Math.max(0, torso().upZ()) / standingZ);
            if (Double.isNaN(upAt) && standsUp()) upAt = simTime() - t0;
        }
        double motionEnd = simTime() - t0;
        boolean stood = true;
        for (int i = 0; i < 50 && stood; i++) {          // must still stand 1 s later
            cycle(MotionRequest.NONE);
            stood = !fallen();
            // the monitor's picture can lag up to 1 s behind (session 6: a robot standing at the end of the
            // get-up was still shown half up): an "up" first seen now counts, timed when seen
            if (stood && Double.isNaN(upAt) && standsUp()) upAt = simTime() - t0;
        }
        if (again < 3 && voided("getup " + lying)) {
            g.tries--;
            row.tally.unmeasured("getup", "the referee stopped play during the get-up (measured again)");
            getUpQuietly();
            getUp(row, lying, again + 1);
            return;
        }
        row.tally.measured("getup");
        boolean ok = stood && !Double.isNaN(upAt);
        boolean walkFell = false;
        if (ok) {
            g.ok++;
            g.time.add(upAt);
            if (opt.getupWalkSeconds() > 0) {
                WalkController walk = new WalkController(WalkConfig.forType(row.type), row.type, MotionConfig.DEFAULT);
                WalkVelocity v = new WalkVelocity(WalkConfig.forType(row.type).maxForward(), 0, 0);
                for (int i = 0; i < opt.getupWalkSeconds() / 0.02 && !walkFell; i++) {
                    receive();
                    cycles++;
                    out.reset();
                    walk.step(last.joints(), last.gyro(), last.acc(), v).appendTo(out).syn();
                    rig.send(out.text());
                    walkFell = fallen();
                }
                g.walks++;
                if (walkFell) g.walkFalls++;
            }
        }
        MonitorScene.Pose e = torso();
        System.err.printf(Locale.ROOT, "  getup %-11s %-14s %s  up at %.2f s, motion %.2f s, best %.2f, end z %.3f up %.2f%s%n", lying, motion,
                ok ? "ok    " : "FAILED", upAt, motionEnd, best, e.z(), e.upZ(), walkFell ? ", fell in the walk after" : "");
        if (!ok || walkFell) getUpQuietly();
    }

    /** Up again: torso upright within about 25° and at three quarters of its standing height. */
    private boolean standsUp() {
        MonitorScene.Pose p = torso();
        return p.upZ() > 0.9 && p.z() > 0.75 * standingZ;
    }

    // --- dives -------------------------------------------------------------------------------------

    /** Decay rate of a rolling ball, 1/s (agent's AgentConfig.Keeper.ballDecay, scripts/ball-decay). */
    private static final double BALL_DECAY = 1.06;

    private void dives(Row row) throws IOException {
        for (String motion : List.of("dive_left", "dive_right")) {
            DiveStats st = row.dives.computeIfAbsent(motion, m -> new DiveStats());
            dive(row, motion, motion.endsWith("_left") ? 1 : -1, st);
        }
    }

    /**
     * One dive from a standing start, the keeper facing +x: a shot rolls along x, 3 m out, passing the
     * keeper's centre {@code --dive-offset} to the diving side and crossing the keeper's line
     * {@code --shot-seconds} after the dive is requested (in the same cycle as the shot). Measured:
     * the time until the torso is down (the bench's fall test), the lateral reach (the farthest body
     * part's centre to that side of the start, over 2.5 s) and when 90 % of it was reached; the shot
     * counts as stopped when the ball never gets 0.5 m behind the keeper's start (its goal line when
     * it stands on its spot, AgentConfig.Keeper.spotOffset).
     */
    private void dive(Row row, String motion, int side, DiveStats st) throws IOException {
        double x0 = -3, y0 = 3;
        String unplaced = place(x0, y0);
        if (unplaced != null) {
            notMeasured(row, motion, unplaced);
            return;
        }
        row.tally.measured(motion);
        MonitorScene.Pose p = torso();
        double startX = p.x(), startY = p.y();
        double distance = 3;
        double v = distance * BALL_DECAY / (1 - Math.exp(-BALL_DECAY * opt.shotSeconds()));
        double ballY = startY + side * opt.diveOffset();
        trainer(String.format(Locale.ROOT, "(ball (pos %.3f %.3f 0.042) (vel %.3f 0 0))", startX + distance, ballY, -v));
        double t0 = simTime(), down = Double.NaN, reach = -1, minBallX = Double.POSITIVE_INFINITY;
        double[] reachAt = new double[125];
        for (int i = 0; i < 200; i++) {
            cycle(onceRequest(motion, true));
            double t = simTime() - t0;
            if (Double.isNaN(down) && fallen()) down = t;
            List<double[]> parts;
            parts = rig.scene(sc -> sc.parts(1, "Left"));
            if (i < reachAt.length && parts != null) {
                double m = -1;
                for (double[] q : parts) m = Math.max(m, side * (q[1] - startY));
                reach = Math.max(reach, m);
                reachAt[i] = reach;
            }
            double[] b = ball();
            if (b != null) minBallX = Math.min(minBallX, b[0]);
        }
        double reachSeconds = Double.NaN;
        for (int i = 0; i < reachAt.length; i++) if (reachAt[i] >= 0.9 * reach) { reachSeconds = (i + 1) * 0.02; break; }
        boolean stopped = minBallX > startX - 0.5;
        st.downSeconds.add(down);
        st.reach.add(reach);
        st.reachSeconds.add(reachSeconds);
        st.shots++;
        if (stopped) st.stopped++;
        System.err.printf(Locale.ROOT, "  %s: down after %.2f s, reach %.2f m (90%% after %.2f s), shot at %.2f m %s%n",
                motion, down, reach, reachSeconds, opt.diveOffset(), stopped ? "stopped" : "passed");
        trainer(String.format(Locale.ROOT, "(ball (pos %.3f %.3f 0.042) (vel 0 0 0))", startX + 6, startY)); // the next place() stands it up
    }

    // --- report -------------------------------------------------------------------------------

    private static double mean(List<Double> l) {
        return l.stream().filter(d -> !Double.isNaN(d)).mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
    }

    static double median(List<Double> l) {
        double[] d = l.stream().filter(x -> !Double.isNaN(x)).mapToDouble(Double::doubleValue).sorted().toArray();
        if (d.length == 0) return Double.NaN;
        return d.length % 2 == 1 ? d[d.length / 2] : (d[d.length / 2 - 1] + d[d.length / 2]) / 2;
    }

    private static double min(List<Double> l) {
        return l.stream().filter(d -> !Double.isNaN(d)).mapToDouble(Double::doubleValue).min().orElse(Double.NaN);
    }

    /** The kick and dive tables (only for the trials that ran). */
    private void printKicksAndDives(List<Row> rows) {
        if (rows.stream().anyMatch(r -> !r.kicks.isEmpty())) {
            System.out.println("type | kick motion      | distance m median / min / mean | dir err deg mean / max | falls | measured");
            for (Row r : rows)
                for (var e : r.kicks.entrySet()) {
                    KickStats k = e.getValue();
                    double maxErr = k.dirError.stream().filter(d -> !Double.isNaN(d)).mapToDouble(Double::doubleValue).max().orElse(Double.NaN);
                    if (k.distance.isEmpty()) {
                        System.out.printf(Locale.ROOT, "%4d | %-16s | no kick measured (below)       |                        |       | 0/%d%n", r.type, e.getKey(), k.tries);
                        continue;
                    }
                    System.out.printf(Locale.ROOT, "%4d | %-16s | %6.2f / %5.2f / %5.2f         | %5.1f / %5.1f          | %d/%-3d | %d/%d%n", r.type, e.getKey(),
                            median(k.distance), min(k.distance), mean(k.distance), mean(k.dirError), maxErr, k.falls, k.distance.size(), k.distance.size(), k.tries);
                }
        }
        if (rows.stream().anyMatch(r -> !r.dives.isEmpty())) {
            System.out.printf(Locale.ROOT, "type | dive       | down s median | reach m median / min | 90%% reach s median | shots at %.2f m stopped%n", opt.diveOffset());
            for (Row r : rows)
                for (var e : r.dives.entrySet()) {
                    DiveStats d = e.getValue();
                    System.out.printf(Locale.ROOT, "%4d | %-10s | %14.2f | %6.2f / %5.2f        | %18.2f | %d/%d%n", r.type, e.getKey(),
                            median(d.downSeconds), median(d.reach), min(d.reach), median(d.reachSeconds), d.stopped, d.shots);
                }
        }
    }

    /** False, with a line on stderr for each, when some figure got no measured trial (the bench then exits with status 3). */
    private static boolean everyFigureMeasured(List<Row> rows) {
        boolean all = true;
        for (Row r : rows) {
            for (String f : r.tally.nothingMeasured()) {
                System.err.printf(Locale.ROOT, "motion-bench: type %d %s: no trial measured anything%n", r.type, f);
                all = false;
            }
        }
        return all;
    }

    private static double max(List<Double> l) { return l.stream().mapToDouble(Double::doubleValue).max().orElse(Double.NaN); }

    private void print(List<Row> rows) {
        printKicksAndDives(rows);
        System.out.println("type | walk m/s | falls | turn L deg/s | turn R deg/s | kick m (dir err deg) | strong kick m (dir err deg) | get-up ok | get-up s");
        double walk = 0, turn = 0, kick = 0, strong = 0, getupS = 0, falls = 0, minutes = 0;
        int tries = 0, ok = 0;
        for (Row r : rows) {
            List<Double> times = new ArrayList<>(r.front.time);
            times.addAll(r.back.time);
            int rt = r.front.tries + r.back.tries, rk = r.front.ok + r.back.ok;
            System.out.printf(Locale.ROOT, "%4d | %8.3f | %5d | %12.1f | %12.1f | %8.2f (%5.1f) | %8.2f (%5.1f) | %3d/%-3d | %6.2f%n",
                    r.type, mean(r.walk), r.falls, mean(r.turnL), mean(r.turnR), mean(r.kick), mean(r.kickDir),
                    mean(r.strong), mean(r.strongDir), rk, rt, mean(times));
            walk += mean(r.walk);
            turn += (mean(r.turnL) + mean(r.turnR)) / 2;
            kick += mean(r.kick);
            strong += mean(r.strong);
            getupS += mean(times);
            falls += r.falls;
            minutes += r.walkMinutes;
            tries += rt;
            ok += rk;
        }
        if (opt.runs("getup") && tries > 0) {
            System.out.println("type | get-up | ok    | median s | max s | walk after: falls/runs");
            for (Row r : rows) {
                for (Row.Getups g : List.of(r.front, r.back)) {
                    System.out.printf(Locale.ROOT, "%4d | %-6s | %2d/%-2d | %8.2f | %5.2f | %d/%d%n", r.type, g == r.front ? "front" : "back",
                            g.ok, g.tries, median(g.time), max(g.time), g.walkFalls, g.walks);
                }
            }
        }
        // the trials that measured nothing, with their reasons, before the summary (still the last line)
        for (Row r : rows) for (String line : r.tally.lines()) System.out.printf(Locale.ROOT, "type %d %s%n", r.type, line);
        int n = rows.size();
        System.out.printf(Locale.ROOT, "walk_mps=%.3f turn_dps=%.1f kick_m=%.2f strong_kick_m=%.2f getup_success=%.2f getup_s=%.2f falls_per_min=%.2f%n",
                walk / n, turn / n, kick / n, strong / n, tries == 0 ? Double.NaN : (double) ok / tries, getupS / n,
                minutes == 0 ? Double.NaN : falls / minutes);
    }
}

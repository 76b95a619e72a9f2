package phalanx.bench.mj;

import phalanx.comm.mj.MjActions;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.FrameWriter;
import phalanx.match.MjServerProcess;
import phalanx.motion.t1.JointCommand;
import phalanx.motion.t1.T1Gait;
import phalanx.motion.t1.T1GaitConfig;
import phalanx.motion.t1.T1Kick;
import phalanx.motion.t1.T1KickConfig;
import phalanx.motion.t1.T1GetUp;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The T1 gait's bench on rcssservermj (scripts/phalanx bench t1): starts its own headless sync server, connects
 * one T1 and runs trials on ground truth (torso_pos, torso_quat). The game stays in BeforeKickOff, where the
 * server lets the agent beam (a beam resets the robot: joints to zero, dropped standing) and does not penalise
 * a robot on the ground, so no monitor command is needed.
 *
 * <ul>
 *   <li>stand: the standing pose for --seconds (default 30); fell or not.</li>
 *   <li>walk: forward at --speed m/s for --seconds (default 60); mean speed along the start heading from
 *       torso_pos over the walking time; a fall (torso up-axis tilted more than 60 deg) is counted, the robot
 *       is beamed back and walks on.</li>
 *   <li>turn: --turn deg/s on the spot for --seconds (default 20); mean turn rate from torso_quat's yaw.</li>
 *   <li>walkturn: --phase seconds (5) of walking at --speed, then as long turning at --turn on the spot, in turn for
 *       --seconds (default 60), as the agent switches; the walking phases' speed along the torso's heading and the
 *       turning phases' rate, each over its phases, and the falls.</li>
 * </ul>
 * Each walk and turn trial starts with 2 s of standing after the beam (not counted).
 */
public final class T1Bench {
    static final double FALL_TILT_DEG = 60;
    static final double SETTLE_S = 2.0;
    static final int TRACE_EVERY = Integer.getInteger("t1.trace", 25);

    private final FrameReader in;
    private final FrameWriter out;
    private final MjPerceptionParser parser = new MjPerceptionParser();
    private MjPerception p;
    private final boolean verbose;

    private final MjServerProcess server;
    /** The ball's world position from the monitor stream (its scene graph), null until the first one. */
    private volatile double[] ball;
    private volatile double ballAt = -1;

    private T1Bench(Socket s, boolean verbose, MjServerProcess server) throws IOException {
        this.in = new FrameReader(new BufferedInputStream(s.getInputStream()));
        this.out = new FrameWriter(new BufferedOutputStream(s.getOutputStream()));
        this.verbose = verbose;
        this.server = server;
        server.onMonitorMessage(m -> {
            double[] b = phalanx.match.MjMonitor.ball(m);
            if (b != null) {
                ball = b;
                ballAt = simTime(m);
            }
        });
    }

    private static double simTime(String m) {
        int at = m.indexOf("(gt 1 0)");
        if (at < 0) return -1;
        int end = m.indexOf(')', at + 8);
        try {
            return Double.parseDouble(m.substring(at + 8, end).trim());
        } catch (RuntimeException e) {
            return -1;
        }
    }

    public record Result(String trial, double seconds, int falls, double commanded, double measured,
                         double lateral, double yawDeg) {
        String line() {
            return switch (trial) {
                case "walkturn" -> String.format(Locale.ROOT, "walkturn %5.1f s  walking %.3f m/s (commanded %.2f)  turning %.1f deg/s (commanded %.1f)  falls %d",
                        seconds, measured, commanded, yawDeg, lateral, falls);
                case "stand" -> String.format(Locale.ROOT, "stand  %5.1f s  %s", seconds, falls == 0 ? "stood" : "FELL (" + falls + ")");
                case "walk" -> String.format(Locale.ROOT, "walk   %5.1f s  commanded %.2f m/s  measured %.3f m/s  lateral drift %.3f m/s  yaw drift %.1f deg  falls %d",
                        seconds, commanded, measured, lateral, yawDeg, falls);
                default -> String.format(Locale.ROOT, "turn   %5.1f s  commanded %.1f deg/s  measured %.1f deg/s  drift %.3f m/s  falls %d",
                        seconds, commanded, measured, lateral, falls);
            };
        }
    }

    /** One perception in, one message out. */
    private void cycle(String message) throws IOException {
        out.write(message);
        in.next();
        try {
            p = parser.parse(in.text());
        } catch (Exception e) {
            throw new IOException("unparsable perception: " + e, e);
        }
    }

    private static String joints(List<JointCommand> cmds) {
        MjActions a = new MjActions();
        for (JointCommand c : cmds) a.joint(c.actuator(), c.qDeg(), c.dqDeg(), c.kp(), c.kd(), c.tau());
        return a.build();
    }

    static double tiltDeg(double[] q) {
        double x = q[1], y = q[2];
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, 1 - 2 * (x * x + y * y)))));
    }

    static double yaw(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        return Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
    }

    static double roll(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        return Math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
    }

    static double pitch(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        return Math.asin(Math.max(-1, Math.min(1, 2 * (w * y - z * x))));
    }

    private void trace(String what, double t) {
        System.out.printf(Locale.ROOT, "  %s t %5.2f pos %.3f %.3f %.3f tilt %.1f roll %.1f pitch %.1f yaw %.1f%n", what, t, p.pos()[0], p.pos()[1], p.pos()[2],
                tiltDeg(p.quat()), Math.toDegrees(roll(p.quat())), Math.toDegrees(pitch(p.quat())), Math.toDegrees(yaw(p.quat())));
        if (System.getenv("T1_JOINTS") != null) {
            StringBuilder sb = new StringBuilder("    L");
            for (int k = 1; k <= 6; k++) sb.append(String.format(Locale.ROOT, " %.1f", p.joints().get("q_llj" + k)[0]));
            sb.append("  R");
            for (int k = 1; k <= 6; k++) sb.append(String.format(Locale.ROOT, " %.1f", p.joints().get("q_rlj" + k)[0]));
            System.out.println(sb);
        }
    }

    private void feed(T1Gait gait) {
        double[] g = p.gyro();
        gait.feedback(roll(p.quat()), pitch(p.quat()), Math.toRadians(g[0]), Math.toRadians(g[1]));
    }

    /** Beams to (x, y, heading) and stands for SETTLE_S; returns false if it fell meanwhile. */
    private boolean reset(T1Gait gait, double x, double y, double thetaDeg) throws IOException {
        gait.feedback(0, 0, 0, 0); // the fallen attitude must not steer the first cycles after the beam
        cycle(MjActions.beam(x, y, thetaDeg));
        cycle(joints(gait.stand()));
        cycle(joints(gait.stand()));
        for (int i = 0; i < SETTLE_S / 0.02; i++) {
            feed(gait);
            cycle(joints(gait.stand()));
            if (verbose && i % 10 == 0) trace("settle", i * 0.02);
        }
        return tiltDeg(p.quat()) < FALL_TILT_DEG;
    }

    Result stand(T1Gait gait, double seconds) throws IOException {
        reset(gait, -10, 0, 0);
        int falls = 0;
        for (int i = 0; i < seconds / 0.02; i++) {
            feed(gait);
            cycle(joints(gait.stand()));
            if (verbose && i % 50 == 0) trace("stand", i * 0.02);
            if (tiltDeg(p.quat()) > FALL_TILT_DEG) { falls++; break; }
        }
        return new Result("stand", seconds, falls, 0, 0, 0, 0);
    }

    /** Walk (turnDegS = 0) or turn (speed = 0) trial. */
    Result move(T1Gait gait, String trial, double speed, double turnDegS, double seconds) throws IOException {
        double startX = trial.equals("walk") ? -22 : -10;
        int falls = 0;
        double along = 0, lateral = 0, yawSum = 0, time = 0;
        reset(gait, startX, 0, 0);
        double[] p0 = p.pos().clone();
        double y0 = yaw(p.quat()), lastYaw = y0, segYaw = 0;
        int n = (int) Math.round(seconds / 0.02);
        for (int i = 0; i < n; i++) {
            feed(gait);
            cycle(joints(gait.next(speed, 0, turnDegS)));
            time += 0.02;
            double yw = yaw(p.quat());
            double dy = yawStep(lastYaw, yw);
            segYaw += dy;
            lastYaw = yw;
            if (verbose && i % TRACE_EVERY == 0) trace(trial, time);
            boolean fell = tiltDeg(p.quat()) > FALL_TILT_DEG;
            if (fell || i == n - 1) {
                // the segment's progress in the start heading's frame
                double dx = p.pos()[0] - p0[0], dyy = p.pos()[1] - p0[1];
                double c = Math.cos(y0), s = Math.sin(y0);
                along += c * dx + s * dyy;
                lateral += -s * dx + c * dyy;
                yawSum += segYaw;
            }
            if (fell) {
                falls++;
                if (verbose) System.out.printf(Locale.ROOT, "  fell at t %.2f%n", time);
                if (i < n - 1) {
                    reset(gait, startX, 0, 0);
                    p0 = p.pos().clone();
                    y0 = yaw(p.quat());
                    lastYaw = y0;
                    segYaw = 0;
                }
            }
        }
        if (trial.equals("walk"))
            return new Result(trial, seconds, falls, speed, along / time, lateral / time, Math.toDegrees(yawSum));
        return new Result(trial, seconds, falls, turnDegS, Math.toDegrees(yawSum) / time, Math.hypot(along, lateral) / time, 0);
    }

    /**
     * Walk and turn in turn: phaseS of walking forward at speed, phaseS of turning on the spot at turnDegS, and so
     * on. Per cycle the torso's progress along its own heading counts in the walking phases and its yaw change in the
     * turning ones (so the speed includes the first, slower steps of each walking phase). A fall is counted, the
     * robot beamed back, and the schedule goes on.
     */
    Result walkTurn(T1Gait gait, double speed, double turnDegS, double seconds, double phaseS) throws IOException {
        int falls = 0;
        double walked = 0, walkTime = 0, turned = 0, turnTime = 0;
        reset(gait, -10, 0, 0);
        double[] last = p.pos().clone();
        double lastYaw = yaw(p.quat());
        int n = (int) Math.round(seconds / 0.02), perPhase = (int) Math.round(phaseS / 0.02);
        for (int i = 0; i < n; i++) {
            boolean walking = (i / perPhase) % 2 == 0;
            feed(gait);
            cycle(joints(walking ? gait.next(speed, 0, 0) : gait.next(0, 0, turnDegS)));
            double yw = yaw(p.quat()), dyaw = yawStep(lastYaw, yw);
            double h = lastYaw + dyaw / 2;
            if (walking) {
                walked += Math.cos(h) * (p.pos()[0] - last[0]) + Math.sin(h) * (p.pos()[1] - last[1]);
                walkTime += 0.02;
            } else {
                turned += dyaw;
                turnTime += 0.02;
            }
            last = p.pos().clone();
            lastYaw = yw;
            if (verbose && i % TRACE_EVERY == 0) trace(walking ? "walk" : "turn", i * 0.02);
            if (tiltDeg(p.quat()) > FALL_TILT_DEG) {
                falls++;
                if (verbose) System.out.printf(Locale.ROOT, "  fell at t %.2f (%s)%n", i * 0.02, walking ? "walking" : "turning");
                if (i < n - 1) {
                    reset(gait, -10, 0, 0);
                    last = p.pos().clone();
                    lastYaw = yaw(p.quat());
                }
            }
        }
        // commanded turn in `lateral`, measured turn rate in `yawDeg`
        return new Result("walkturn", seconds, falls, speed, walked / Math.max(walkTime, 1e-9), turnDegS,
                Math.toDegrees(turned) / Math.max(turnTime, 1e-9));
    }

    /** The yaw change from {@code from} to {@code to} (rad), the short way round. */
    static double yawStep(double from, double to) {
        double d = to - from;
        while (d > Math.PI) d -= 2 * Math.PI;
        while (d < -Math.PI) d += 2 * Math.PI;
        return d;
    }

    /** {@code FIELD=VALUE} of an option, or a message naming the option. */
    static String[] fieldValue(String option, String arg) {
        String[] kv = arg.split("=", 2);
        if (kv.length != 2 || kv[0].isEmpty()) throw new IllegalArgumentException(option + " FIELD=VALUE, got '" + arg + "'");
        return kv;
    }

    /** One kick of the kick trial: the ball's travel (m), its direction against the robot's heading (deg), a fall. */
    record KickResult(double distance, double directionErrorDeg, boolean fell, String note) {
        String line(int i, boolean left) {
            return String.format(Locale.ROOT, "kick %2d  %s foot  ball %.2f m  direction error %+.1f deg  %s%s", i, left ? "left " : "right",
                    distance, directionErrorDeg, fell ? "FELL" : "stood", note.isEmpty() ? "" : "  (" + note + ")");
        }
    }

    static final double BALL_RADIUS = 0.11;       // soccer_ball.py
    static final double BALL_STILL_M = 0.01;      // the ball counts as stopped when it moved less in BALL_WATCH_S
    static final double BALL_WATCH_S = 0.5;
    static final double BALL_MAX_S = 12;
    static final int KICK_TRACE_EVERY = Integer.getInteger("t1.kicktrace", 5);

    /**
     * The kick trial: beam to (-10, 0) facing +x, stand SETTLE_S, place the ball (monitor {@code (ball (pos x y z)
     * (vel 0 0 0))}) at the kick config's spot in front of the kicking foot, stand 0.5 s, kick, then stand and watch
     * the ball (from the monitor's scene graph) until it stops. A fall is a torso tilt over 60 deg from the kick's
     * start until the ball stopped.
     */
    KickResult kick(T1Gait gait, T1Kick kick, boolean left, double jx, double jy) throws IOException {
        ball = null;
        if (!reset(gait, -10, 0, 0)) return new KickResult(0, 0, true, "fell while standing before the kick");
        double h = yaw(p.quat());
        double[] tp = p.pos();
        double kx = kick.config().ballX() + jx, ky = (left ? 1 : -1) * kick.config().ballY() + jy;
        double bx = tp[0] + Math.cos(h) * kx - Math.sin(h) * ky, by = tp[1] + Math.sin(h) * kx + Math.cos(h) * ky;
        server.command(String.format(Locale.ROOT, "(ball (pos %.3f %.3f %.3f) (vel 0 0 0))", bx, by, BALL_RADIUS));
        for (int i = 0; i < 25; i++) {
            feed(gait);
            cycle(joints(gait.stand()));
        }
        double[] b0 = ball;
        if (b0 == null || Math.hypot(b0[0] - bx, b0[1] - by) > 0.05)
            return new KickResult(0, 0, false, "the monitor did not show the placed ball: " + java.util.Arrays.toString(b0));
        Optional<String> refused = kick.start(left, tiltDeg(p.quat()) < FALL_TILT_DEG);
        if (refused.isPresent()) return new KickResult(0, 0, false, "refused: " + refused.get());
        boolean fell = false;
        double t = 0;
        while (kick.active()) {
            cycle(joints(kick.next()));
            t += 0.02;
            fell |= tiltDeg(p.quat()) > FALL_TILT_DEG;
            if (verbose && Math.round(t / 0.02) % KICK_TRACE_EVERY == 0) {
                trace(kick.phaseName(), t);
                double[] q = new double[6];
                String pre = left ? "q_llj" : "q_rlj";
                for (int k = 0; k < 6; k++) q[k] = Math.toRadians(p.joints().get(pre + (k + 1))[0]);
                double[] f = new phalanx.motion.t1.T1LegKinematics(gait.config(), left).footPosition(q);
                double[] bl = ball;
                System.out.printf(Locale.ROOT, "    kicking foot (torso frame, measured) %.3f %.3f %.3f  ball %.3f %.3f %.3f%n", f[0], f[1], f[2], bl[0], bl[1], bl[2]);
            }
        }
        gait.stand();
        double[] last = ball;
        for (int i = 1; i <= BALL_MAX_S / 0.02; i++) {
            feed(gait);
            cycle(joints(gait.stand()));
            fell |= tiltDeg(p.quat()) > FALL_TILT_DEG;
            if (i % Math.round(BALL_WATCH_S / 0.02) == 0) {
                double[] b = ball;
                if (Math.hypot(b[0] - last[0], b[1] - last[1]) < BALL_STILL_M) break;
                last = b;
            }
        }
        double[] b1 = ball;
        double dx = b1[0] - b0[0], dy = b1[1] - b0[1];
        double err = Math.toDegrees(Math.atan2(dy, dx) - h);
        while (err > 180) err -= 360;
        while (err < -180) err += 360;
        return new KickResult(Math.hypot(dx, dy), err, fell, "");
    }

    /** {@code jitter}: the ball is placed up to this far off the kick's spot in x and y (uniform, seeded: each run the same). */
    void kickTrial(T1Gait gait, T1Kick kick, int n, String foot, double jitter) throws IOException {
        java.util.Random rnd = new java.util.Random(20);
        List<Double> dist = new ArrayList<>();
        int falls = 0;
        long wall = System.nanoTime();
        for (int i = 1; i <= n; i++) {
            boolean left = foot.equals("left") || (foot.equals("both") && i % 2 == 0);
            KickResult r = kick(gait, kick, left, jitter * (2 * rnd.nextDouble() - 1), jitter * (2 * rnd.nextDouble() - 1));
            System.out.println(r.line(i, left));
            System.out.flush();
            if (r.note().isEmpty() || r.fell()) dist.add(r.distance());
            if (r.fell()) falls++;
        }
        System.out.printf(Locale.ROOT, "kick summary: %d kicks (%s foot)  ball median %.2f m  min %.2f  max %.2f  falls %d   (%.0f s wall)%n",
                n, foot, median(dist), dist.stream().mapToDouble(d -> d).min().orElse(Double.NaN),
                dist.stream().mapToDouble(d -> d).max().orElse(Double.NaN), falls, (System.nanoTime() - wall) / 1e9);
    }

    /** One get-up of the get-up trial: how it lay, the get-ups it took, whether it stood, how long that took. */
    record GetUpResult(String lay, String side, long getUps, boolean stood, double seconds, String note) {
        String line(int i) {
            return String.format(Locale.ROOT, "get-up %2d  %-10s lay on its %-10s  %s  after %d get-up%s, up %.2f s after it lay still%s", i, lay, side,
                    stood ? "STOOD" : "failed", getUps, getUps == 1 ? "" : "s", seconds, note.isEmpty() ? "" : "  (" + note + ")");
        }
    }

    static final double LIE_SETTLE_S = 1.0;     // after the drop, before the agent's get-up logic runs
    static final double STAND_AFTER_S = 3.0;    // standing after a get-up; stood = upright (tilt < 30 deg) through it
    static final double UPRIGHT_TILT_DEG = 30;
    static final double GIVE_UP_S = 15;         // the referee takes a field player off after 15 s on the ground

    /** Lying on the front (torso x axis down), back (x up) or a side, from the torso's attitude. */
    static String lyingOn(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        double fz = 2 * (x * z - w * y);   // world z of the torso's forward (x) axis
        double lz = 2 * (y * z + w * x);   // ... of its left (y) axis
        if (Math.abs(fz) >= Math.abs(lz)) return fz < 0 ? "front" : "back";
        return lz < 0 ? "left side" : "right side";
    }

    /**
     * One get-up as the agent does it ({@link T1GetUp}, the player's class): beam and stand, then lay the robot
     * down. "front"/"back": the monitor places it ({@code (agent ... (move3d x y z q))}: joints to zero, face down or
     * up, a seeded random heading and up to 10 deg of roll) and it lies LIE_SETTLE_S. "fall-front"/"fall-back": it
     * falls by itself from the stand (knees straight and toes down tip it forward; hips and knees bent, it sits down
     * and falls backwards) until the torso is tilted past 60 deg. Then T1GetUp runs each cycle (it waits until the robot lies
     * still, plays the get-up for the side, and again if it is still down), the gait's stand with feedback between;
     * it stood when upright for STAND_AFTER_S after a get-up; given up after GIVE_UP_S.
     */
    GetUpResult getUp(T1Gait gait, T1GetUp getUp, String lay, java.util.Random rnd) throws IOException {
        if (!reset(gait, -10, 0, 0)) return new GetUpResult(lay, "-", 0, false, 0, "fell while standing before");
        double yaw = Math.toRadians(360 * rnd.nextDouble()), roll = Math.toRadians(10 * (2 * rnd.nextDouble() - 1));
        if (lay.startsWith("fall")) {
            boolean back = lay.equals("fall-back");   // sitting down backwards; knees straight and toes down tips it forward
            List<JointCommand> tip = new ArrayList<>();
            for (JointCommand j : gait.stand()) {
                double q = j.qDeg();
                if (j.actuator().matches("[lr]le1")) q = back ? -90 : 0;
                if (j.actuator().matches("[lr]le4")) q = back ? 90 : 0;
                if (j.actuator().matches("[lr]le5")) q = back ? -10 : 20;
                tip.add(new JointCommand(j.actuator(), q, 0, j.kp(), j.kd(), 0));
            }
            for (int i = 0; i < 150 && tiltDeg(p.quat()) < 60; i++) cycle(joints(tip));
        } else {
            double pitch = Math.toRadians(lay.equals("front") ? 90 : -90);
            double[] q = mul(axis(0, 0, 1, yaw), mul(axis(0, 1, 0, pitch), axis(1, 0, 0, roll)));
            server.command(String.format(Locale.ROOT, "(agent (unum 2) (team Phalanx) (move3d -10 0 0.35 %.5f %.5f %.5f %.5f))", q[0], q[1], q[2], q[3]));
            for (int i = 0; i < LIE_SETTLE_S / 0.02; i++) cycle(joints(gait.stand()));
        }
        String side = lyingOn(p.quat());
        String placed = lay.startsWith("fall") ? "" : String.format(Locale.ROOT, "placed heading %.0f deg, roll %.1f deg", Math.toDegrees(yaw), Math.toDegrees(roll));
        long before = getUp.getUps();
        getUp.reset();   // t starts at 0 again: a wait or a recovery left from the trial before would compare against its times
        double t = 0, upSince = -1, stillAt = -1;
        gait.feedback(0, 0, 0, 0);
        while (t < GIVE_UP_S) {
            MjPerception now = p;
            List<JointCommand> g = getUp.update(now.quat(), now.gyro(), a -> phalanx.agent.mj.MjRuntime.measuredDeg(now, a), t);
            if (g != null && stillAt < 0) stillAt = t;
            if (g == null) feed(gait);
            cycle(joints(g != null ? g : gait.stand()));
            t += 0.02;
            if (verbose && Math.round(t / 0.02) % KICK_TRACE_EVERY == 0) trace(g != null ? getUp.playing() : "stand", t);
            // the recovery stand after the motion counts as standing (it ends in the agent's stand, a fall in it is a failure)
            boolean up = (g == null || getUp.state() == T1GetUp.State.RECOVERING) && getUp.getUps() > before && tiltDeg(p.quat()) < UPRIGHT_TILT_DEG;
            if (!up) upSince = -1;
            else if (upSince < 0) upSince = t;
            if (upSince >= 0 && t - upSince >= STAND_AFTER_S)
                return new GetUpResult(lay, side, getUp.getUps() - before, true, upSince - stillAt, placed);
        }
        return new GetUpResult(lay, side, getUp.getUps() - before, false, t, "still down after " + GIVE_UP_S + " s" + (placed.isEmpty() ? "" : "; " + placed));
    }

    static double[] axis(double x, double y, double z, double a) {
        double s = Math.sin(a / 2);
        return new double[]{Math.cos(a / 2), x * s, y * s, z * s};
    }

    static double[] mul(double[] a, double[] b) {
        return new double[]{a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
    }

    void getUpTrial(T1Gait gait, T1GetUp getUp, int n, String lying, long seed) throws IOException {
        java.util.Random rnd = new java.util.Random(seed);
        List<String> lays = List.of((lying.equals("both") ? "front,back" : lying).split(","));
        int first = 0, stood = 0;
        List<Double> times = new ArrayList<>();
        long wall = System.nanoTime();
        for (int i = 1; i <= n; i++) {
            GetUpResult r = getUp(gait, getUp, lays.get((i - 1) % lays.size()), rnd);
            System.out.println(r.line(i));
            System.out.flush();
            if (r.stood()) {
                stood++;
                times.add(r.seconds());
                if (r.getUps() == 1) first++;
            }
        }
        System.out.printf(Locale.ROOT, "get-up summary: %d of %d stood at the first try, %d in the end (%s); up after median %.2f s   (%.0f s wall)%n",
                first, n, stood, lying, median(times), (System.nanoTime() - wall) / 1e9);
    }

    static double median(List<Double> v) {
        List<Double> s = new ArrayList<>(v);
        java.util.Collections.sort(s);
        int n = s.size();
        return n == 0 ? Double.NaN : n % 2 == 1 ? s.get(n / 2) : (s.get(n / 2 - 1) + s.get(n / 2)) / 2;
    }

    /** A bad option, with its name: main prints it and exits with status 2. */
    static final class BadOption extends IllegalArgumentException {
        BadOption(String why) { super(why); }
    }

    public static void main(String[] args) throws Exception {
        try {
            run(args);
        } catch (BadOption e) {
            System.err.println("t1-bench: " + e.getMessage() + " (scripts/phalanx bench t1 --help)");
            System.exit(2);
        }
    }

    /** The bench with these options; a bad option throws {@link BadOption} before any server starts. */
    static void run(String[] args) throws Exception {
        String trial = "all";
        double seconds = -1, speed = 0.6, turn = 60;
        int port = 4100;
        boolean verbose = false;
        T1GaitConfig config = T1GaitConfig.defaults();
        T1GaitConfig.Blend blend = null;
        double phase = 5;
        T1KickConfig kickConfig = T1KickConfig.defaults();
        int kicks = 10;
        double jitter = 0;
        String foot = "right";
        String lying = "both";
        int getups = 10;
        long seed = 20;
        Path motionDir = Path.of("motions", "t1");
        T1GetUp.Config getUpConfig = T1GetUp.Config.DEFAULT;
        T1GaitConfig recovery = T1GaitConfig.getUpRecovery();
        for (int i = 0; i < args.length; i++) {
            String option = args[i];
            try {
                switch (args[i]) {
                    case "--trial" -> trial = args[++i];
                    case "--seconds" -> seconds = Double.parseDouble(args[++i]);
                    case "--speed" -> speed = Double.parseDouble(args[++i]);
                    case "--turn" -> turn = Double.parseDouble(args[++i]);
                    case "--port" -> port = Integer.parseInt(args[++i]);
                    case "--preset" -> config = switch (args[++i]) {
                        case "walk" -> T1GaitConfig.defaults();
                        case "balanced" -> T1GaitConfig.balanced();
                        case "turn" -> T1GaitConfig.turnInPlace();
                        case "blend" -> {
                            blend = T1GaitConfig.Blend.agent();
                            yield T1GaitConfig.balanced();   // the agent's stand (and kick) config
                        }
                        default -> throw new IllegalArgumentException("--preset walk|balanced|turn|blend");
                    };
                    case "--walk-set", "--turn-set" -> {
                        if (blend == null) throw new IllegalArgumentException(args[i] + " after --preset blend");
                        String[] kv = fieldValue(args[i], args[i + 1]);
                        double v = Double.parseDouble(kv[1]);
                        blend = args[i].equals("--walk-set") ? blend.withWalk(blend.walk().with(kv[0], v)) : blend.withTurn(blend.turn().with(kv[0], v));
                        i++;
                    }
                    case "--blend-rate" -> {
                        if (blend == null) throw new IllegalArgumentException("--blend-rate after --preset blend");
                        blend = blend.withRate(Double.parseDouble(args[++i]));
                    }
                    case "--turn-at-speed" -> {
                        if (blend == null) throw new IllegalArgumentException("--turn-at-speed after --preset blend");
                        String[] v = args[++i].split(",");
                        if (v.length != 2) throw new IllegalArgumentException("--turn-at-speed DEG_S,M_S, got '" + args[i] + "'");
                        blend = blend.withTurnAtSpeed(Double.parseDouble(v[0]), Double.parseDouble(v[1]));
                    }
                    case "--decel" -> {
                        if (blend == null) throw new IllegalArgumentException("--decel after --preset blend");
                        blend = blend.withDecel(Double.parseDouble(args[++i]));
                    }
                    case "--phase" -> {
                        phase = Double.parseDouble(args[++i]);
                        if (!(phase >= 0.02)) throw new IllegalArgumentException("--phase S must be at least one cycle (0.02 s), got " + args[i]);
                    }
                    case "--set" -> {
                        String[] kv = args[++i].split("=", 2);
                        config = config.with(kv[0], Double.parseDouble(kv[1]));
                    }
                    case "--kick" -> {
                        String[] kv = args[++i].split("=", 2);
                        kickConfig = kickConfig.with(kv[0], Double.parseDouble(kv[1]));
                    }
                    case "--kicks" -> kicks = Integer.parseInt(args[++i]);
                    case "--ball-jitter" -> jitter = Double.parseDouble(args[++i]);
                    case "--foot" -> {
                        foot = args[++i];
                        if (!foot.equals("left") && !foot.equals("right") && !foot.equals("both"))
                            throw new IllegalArgumentException("--foot left|right|both");
                    }
                    case "--lying" -> {
                        lying = args[++i];
                        for (String l : lying.split(","))
                            if (!List.of("front", "back", "both", "fall-front", "fall-back").contains(l))
                                throw new IllegalArgumentException("--lying front|back|both|fall-front|fall-back, or a comma list of them");
                    }
                    case "--getups" -> getups = Integer.parseInt(args[++i]);
                    case "--seed" -> seed = Long.parseLong(args[++i]);
                    case "--motions" -> motionDir = Path.of(args[++i]);
                    case "--recover" -> getUpConfig = getUpConfig.withRecoverS(Double.parseDouble(args[++i]));
                    case "--getup-set" -> {
                        String[] kv = fieldValue(args[i], args[i + 1]);
                        getUpConfig = getUpConfig.with(kv[0], Double.parseDouble(kv[1]));
                        i++;
                    }
                    case "--recover-set" -> {
                        String[] kv = fieldValue(args[i], args[i + 1]);
                        recovery = recovery.with(kv[0], Double.parseDouble(kv[1]));
                        i++;
                    }
                    case "--verbose" -> verbose = true;
                    case "-h", "--help" -> {
                        System.out.println("""
                                usage: scripts/phalanx bench t1 [--trial stand|walk|turn|walkturn|kick|getup|all] [--seconds S] [--speed M_PER_S]
                                       [--turn DEG_PER_S] [--port P] [--preset walk|balanced|turn|blend] [--set CONFIG_FIELD=VALUE]...
                                       [--walk-set FIELD=VALUE]... [--turn-set FIELD=VALUE]... [--blend-rate PER_S] [--turn-at-speed DEG_S,M_S] [--decel M_S2] [--phase S]
                                       [--kicks N] [--foot left|right|both] [--ball-jitter M] [--kick KICK_FIELD=VALUE]... [--verbose]
                                Starts its own rcssservermj (ports P, P+1; default 4100) and runs the T1 gait's trials:
                                stand 30 s, walk 60 s at --speed (0.6), turn 20 s at --turn (60). Defaults per trial.
                                --preset: T1GaitConfig.defaults() (walk, the default), balanced() or turnInPlace(); --set after it.
                                --preset blend: T1GaitConfig.Blend.agent() (balancedWalk() walking, turnInPlace() turning, blended
                                by the command; balanced() standing; the agent itself walks balanced()): --walk-set/--turn-set change its
                                presets, --blend-rate its rate (share per s), --turn-at-speed its turn limit at and above a speed, --decel its slowing down,
                                --set its stand config.
                                walkturn (not in all): --phase S (5) walking at --speed, --phase S turning at --turn, in turn,
                                --seconds (60); the walking phases' speed, the turning phases' rate, falls.
                                kick (not in all): --kicks N (10) kicks with --foot (right; both alternates), the ball placed in
                                front of the foot (up to --ball-jitter M off it in x and y, seeded); per kick the ball's travel,
                                its direction error and a fall; --kick changes
                                T1KickConfig.defaults(), e.g. --kick swing.kickX=0.25 or --kick legKp=250.
                                getup (not in all): --getups N (10) times laid down by the monitor, --lying front|back|both
                                (both: alternating), or fallen by itself, --lying fall-front|fall-back (a comma list: in turn;
                                --seed N (20) for the placements); the agent's T1GetUp with
                                get_up_front|back.motion from --motions DIR (motions/t1) gets it up, then its recovery stand
                                (--recover S, T1GetUp.RECOVER_S; --recover-set FIELD=VALUE changes its T1GaitConfig.getUpRecovery());
                                --getup-set FIELD=VALUE changes T1GetUp.Config.DEFAULT (e.g. riseBackS=1.2, riseAnkleRateGain=0.05);
                                per get-up whether it stood, at the first try, and how long after lying still.""");
                        return;
                    }
                    default -> throw new IllegalArgumentException("unknown option " + args[i]);
                }
            } catch (NumberFormatException e) {
                throw new BadOption(option + " needs a number, got '" + (i < args.length ? args[i] : "") + "'");
            } catch (ArrayIndexOutOfBoundsException e) {
                throw new BadOption(option + " needs a value");
            } catch (IllegalArgumentException e) {
                throw new BadOption(e.getMessage());
            }
        }
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        if (exe.isEmpty()) {
            System.err.println("rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
            System.exit(2);
        }
        List<Result> results = new ArrayList<>();
        List<String> trials = trial.equals("all") ? List.of("stand", "walk", "turn") : List.of(trial.split(","));
        // rcsssmj 0.2.1 now and then crashes while adding the player (audio_engine a_forward, "operands could not
        // be broadcast", seen about one start in three here): the server is then restarted, up to 5 times.
        for (int attempt = 1; ; attempt++) {
            Path dir = Files.createTempDirectory("t1bench");
            MjServerProcess server = MjServerProcess.start(exe.get(), new MjServerProcess.Settings(port, port + 1, true, false), dir);
            // a bench stopped from outside (a search that kills a candidate, Ctrl-C) must not leave its server holding the ports
            Thread hook = new Thread(server::stop, "t1bench-stop-server");
            Runtime.getRuntime().addShutdownHook(hook);
            try {
                if (!server.awaitReady(120_000)) throw new IOException("rcssservermj not ready: " + Files.readString(server.log()));
                try (Socket s = new Socket("127.0.0.1", port)) {
                    s.setTcpNoDelay(true);
                    s.setSoTimeout(30_000);
                    T1Bench b = new T1Bench(s, verbose, server);
                    try {
                        b.out.write(MjActions.init("Phalanx", 2));
                        b.cycle("(syn)");
                    } catch (IOException e) {
                        if (attempt < 5) {
                            System.err.println("rcssservermj dropped the T1 at its start (" + e.getMessage() + "), restarting it");
                            continue;
                        }
                        throw new IOException("rcssservermj dropped the T1 five times; last log: " + Files.readString(server.log()), e);
                    }
                    for (String t : trials) {
                        T1Gait gait = blend != null ? new T1Gait(blend, config) : new T1Gait(config);
                        if (t.equals("getup")) {
                            b.getUpTrial(gait, T1GetUp.load(motionDir, getUpConfig, recovery), getups, lying, seed);
                            continue;
                        }
                        if (t.equals("kick")) {
                            b.kickTrial(gait, new T1Kick(config, kickConfig), kicks, foot, jitter);
                            continue;
                        }
                        long wall = System.nanoTime();
                        Result r = switch (t) {
                            case "stand" -> b.stand(gait, seconds > 0 ? seconds : 30);
                            case "walk" -> b.move(gait, "walk", speed, 0, seconds > 0 ? seconds : 60);
                            case "turn" -> b.move(gait, "turn", 0, turn, seconds > 0 ? seconds : 20);
                            case "walkturn" -> b.walkTurn(gait, speed, turn, seconds > 0 ? seconds : 60, phase);
                            default -> throw new IllegalArgumentException("unknown trial " + t);
                        };
                        results.add(r);
                        System.out.println(r.line() + String.format(Locale.ROOT, "   (%.0f s wall)", (System.nanoTime() - wall) / 1e9));
                        System.out.flush();
                    }
                    break;
                }
            } finally {
                server.stop();
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException shuttingDown) {
                    // the hook is running: it stops the server itself
                }
            }
        }
        int falls = results.stream().mapToInt(Result::falls).sum();
        StringBuilder sb = new StringBuilder("summary:");
        for (Result r : results) {
            switch (r.trial()) {
                case "stand" -> sb.append(r.falls() == 0 ? " stand ok;" : " stand FELL;");
                case "walk" -> sb.append(String.format(Locale.ROOT, " walk %.3f m/s (cmd %.2f), %d falls in %.0f s;", r.measured(), r.commanded(), r.falls(), r.seconds()));
                case "walkturn" -> sb.append(String.format(Locale.ROOT, " walkturn %.3f m/s (cmd %.2f) / %.1f deg/s (cmd %.0f), %d falls in %.0f s;",
                        r.measured(), r.commanded(), r.yawDeg(), r.lateral(), r.falls(), r.seconds()));
                default -> sb.append(String.format(Locale.ROOT, " turn %.1f deg/s (cmd %.0f), %d falls in %.0f s;", r.measured(), r.commanded(), r.falls(), r.seconds()));
            }
        }
        System.out.println(sb.append(" total falls ").append(falls));
    }
}

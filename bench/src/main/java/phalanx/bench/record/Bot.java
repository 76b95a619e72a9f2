package phalanx.bench.record;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.wire.ServerConnection;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionLibrary;
import phalanx.motion.control.HeadServo;
import phalanx.motion.control.JointVelocities;
import phalanx.motion.control.MotionController;
import phalanx.motion.control.MotionRequest;
import phalanx.motion.walk.WalkConfig;
import phalanx.motion.walk.WalkController;
import phalanx.motion.walk.Odometry;
import phalanx.motion.walk.WalkVelocity;

import java.io.IOException;
import java.util.Locale;

/**
 * One scripted robot of the recorder, driven one message at a time: {@code (init)} answers message 1, the beam
 * message 2 (as in the shared recordings), then its {@link Plan}. The walk is motion's {@code WalkController}, the
 * get-ups are the motion files the agent plays ({@code stand_up_back} when the chest faces more than 30° up, as
 * localization's FallDetector decides, else {@code stand_up_front}), the head follows {@link HeadServo}.
 */
final class Bot {
    /** The accelerometer's forward (+y) reading above which the robot lies on its back: sin 30° of 1 g (LocalizationConfig.fallBackMinDeg). */
    private static final double BACK_ACC_Y = 9.81 * Math.sin(Math.toRadians(30));

    final String team;
    final int unum, type;
    final Side side;
    final Plan plan;
    private final ServerConnection conn;
    private final PerceptionParser parser = new PerceptionParser();
    private final MotionController motions;
    private final EffectorMessage out = new EffectorMessage();
    private WalkController walk;
    private int received, step, inStep, malformed;
    private long completionsAtStart;
    private String getUp;
    private String text;
    private Perception last;
    private Odometry odometry = Odometry.NONE;

    private Bot(String team, int unum, int type, Side side, Plan plan, ServerConnection conn, MotionLibrary library) {
        this.team = team;
        this.unum = unum;
        this.type = type;
        this.side = side;
        this.plan = plan;
        this.conn = conn;
        this.motions = new MotionController(library, MotionConfig.DEFAULT);
    }

    /** Connects and sends {@code (scene …)}; returns the bot and that line (effector line 1). */
    static Bot connect(String host, int port, String team, int unum, int type, Side side, Plan plan, MotionLibrary library) throws IOException {
        Bot b = new Bot(team, unum, type, side, plan, ServerConnection.connect(host, port, 10_000), library);
        b.conn.send(EffectorMessage.scene(type));
        return b;
    }

    String sceneLine() { return EffectorMessage.scene(type); }

    /** A message is waiting. */
    boolean ready() throws IOException { return conn.awaitData(0); }

    /** Messages received so far. */
    int received() { return received; }

    /** Reads the next message; its text exactly as sent (without the length prefix). */
    String read() throws IOException {
        conn.reader().next();
        text = conn.reader().text();
        received++;
        try {
            Perception p = parser.parse(conn.reader().buffer(), 0, conn.reader().length());
            if (p != null) last = p;
        } catch (MalformedMessageException e) {
            malformed++;
        }
        return text;
    }

    Perception last() { return last; }
    int malformed() { return malformed; }

    /** The unum and side the server gave (null when it has not said yet, or said something else). */
    String joinProblem() {
        if (last == null || last.gameState() == null || last.gameState().unum() == 0) return null;
        if (last.gameState().unum() == unum && last.gameState().side() == side) return null;
        return String.format(Locale.ROOT, "%s %d was taken as player %d on the %s, not %d on the %s (restart the server)", team, unum,
                last.gameState().unum(), last.gameState().side(), unum, side);
    }

    /** Past the last step of its plan. */
    boolean done() { return step >= plan.steps().size(); }

    /** Builds and sends the reply to the message just read; returns it. */
    String reply() throws IOException {
        String r = compose();
        conn.send(r);
        return r;
    }

    private String compose() {
        out.reset();
        odometry = Odometry.NONE;
        if (received == 1) return EffectorMessage.init(unum, team);
        if (received == 2) {
            return out.beam(plan.beamX(), plan.beamY(), plan.beamDeg()).syn().text().toString(); // own frame, as the server takes it
        }
        double t = (received - 3) * 0.02;
        JointAngles j = last == null ? JointAngles.none() : last.joints();
        Vector3 acc = last == null ? null : last.acc();
        double now = last == null ? Double.NaN : last.time();
        double yaw = head(j, Joint.HJ1, plan.headYawDeg(t)), pitch = head(j, Joint.HJ2, plan.headPitchDeg(t));
        if (done()) {
            standStill(j, acc, now).appendTo(out, yaw, pitch);
            return out.syn().text().toString();
        }
        Plan.Step s = plan.steps().get(step);
        switch (s.kind()) {
            case WALK -> {
                if (walk == null) walk = new WalkController(WalkConfig.forType(type), type, MotionConfig.DEFAULT);
                walk.step(j, last == null ? null : last.gyro(), acc, s.walk()).appendTo(out, yaw, pitch);
                odometry = walk.odometry();
            }
            case STAND -> standStill(j, acc, now).appendTo(out, yaw, pitch);
            case TIP -> {
                walk = null;
                // every other joint stopped (a hinge keeps its last velocity), both ankle pitches driven, 0 in the last cycle
                double v = inStep == s.cycles() - 1 ? 0 : s.ankle();
                motions.step(now, j, acc, MotionRequest.NONE).with(Joint.LLJ5, v).with(Joint.RLJ5, v).appendTo(out, yaw, pitch);
            }
            case GETUP -> {
                walk = null;
                if (inStep == 0) {
                    getUp = acc != null && acc.y() > BACK_ACC_Y ? "stand_up_back" : "stand_up_front";
                    completionsAtStart = motions.completions();
                }
                motions.step(now, j, acc, MotionRequest.of(getUp).interrupting()).appendTo(out, yaw, pitch);
            }
        }
        advance(s);
        if (down(acc)) odometry = Odometry.NONE;
        return out.syn().text().toString();
    }

    /** The torso leans more than 45° (ACC's up component below g·cos 45°): the plan's walk then moves nothing, and the agent would not walk. */
    static boolean down(Vector3 acc) { return acc != null && acc.z() < 9.81 * Math.cos(Math.toRadians(45)); }

    /** After a walk, the walk standing (it keeps its crouch); else the motion controller idle: every joint held. */
    private JointVelocities standStill(JointAngles j, Vector3 acc, double now) {
        if (walk != null) {
            JointVelocities v = walk.step(j, last.gyro(), acc, WalkVelocity.ZERO);
            odometry = walk.odometry();
            return v;
        }
        return motions.step(now, j, acc, MotionRequest.NONE);
    }

    private void advance(Plan.Step s) {
        inStep++;
        boolean over = inStep >= s.cycles() || (s.kind() == Plan.Kind.GETUP && motions.completions() > completionsAtStart);
        if (over) {
            step++;
            inStep = 0;
        }
    }

    /**
     * The walk's own motion in the cycle of the last reply, as commanded ({@code WalkController.odometry}), what the
     * agent passes to {@code BeliefStore.odometry} after each update; none outside the walk, and none while the robot is
     * down ({@link #down}): a plan's walk may go on while the robot lies, the agent's would not.
     */
    Odometry odometry() { return odometry; }

    /** The get-up motion the last GETUP step played (null before one). */
    String getUpPlayed() { return getUp; }

    private static double head(JointAngles j, Joint joint, double targetDeg) {
        return j.has(joint) ? HeadServo.velocity(targetDeg, j.degrees(joint)) : Double.NaN;
    }

    void close() { conn.close(); }
}

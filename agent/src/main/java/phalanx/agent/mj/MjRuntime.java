package phalanx.agent.mj;

import phalanx.agent.Player;
import phalanx.comm.mj.MjActions;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.team.TeamKey;
import phalanx.model.field.MjField;
import phalanx.motion.t1.JointCommand;
import phalanx.model.robot.T1Model;
import phalanx.motion.t1.T1Gait;
import phalanx.motion.t1.T1GaitConfig;
import phalanx.model.robot.T1Joints;
import phalanx.motion.MotionFileException;
import phalanx.motion.t1.T1GetUp;
import phalanx.motion.t1.T1Kick;
import phalanx.motion.t1.T1KickConfig;

import java.nio.file.Path;

import java.util.List;
import java.util.logging.Logger;

/**
 * One T1 player's cycle on rcssservermj: sense (parse) → model ({@link MjWorld}) → decide (the team channel's rounds,
 * {@link MjTeamTalk}; {@link MjBehaviour})
 * → act (the T1 gait's joint PD commands, the kick's while it plays, a beam when decided). Always answers, also to a message it cannot parse
 * (the last joint commands again), because an agent-sync server waits for every agent each cycle.
 */
public final class MjRuntime {
    private static final Logger LOG = Logger.getLogger(MjRuntime.class.getName());
    private static final int MALFORMED_LOGGED = 5;

    private final MjPerceptionParser parser = new MjPerceptionParser();
    private final MjWorld world;
    private final MjBehaviour behaviour;
    /** balanced(): 0.50 m/s and 38 °/s (60 commanded) with no fall, where defaults() walks 0.6 but falls turning (motion/README.md). */
    private final T1Gait gait = new T1Gait(T1GaitConfig.balanced());
    private final T1Kick kick = new T1Kick(T1GaitConfig.balanced(), T1KickConfig.defaults());
    /** A kick asked for and waiting for the gait's feet to come together, since (game time), or null. */
    private MjBehaviour.Foot pendingKick;
    private double pendingSince, settleUntil, standUntil = Double.NEGATIVE_INFINITY;
    private long kicks, kicksRefused;
    private final MjActions actions = new MjActions();
    private String last = "(syn)";
    private final int unum;
    private final MjTeamTalk talk;
    private long cycles, malformed, beams;

    private final T1GetUp getUp;

    /** With the get-ups of motions/t1 (the project root's). */
    public MjRuntime(String team, int unum, MjField field) throws MotionFileException {
        this(team, unum, field, Player.teamKey(team), Path.of("motions", "t1"));
    }

    /** motionDir: the folder of get_up_front.motion and get_up_back.motion; a bad file stops the start here. */
    public MjRuntime(String team, int unum, MjField field, TeamKey key, Path motionDir) throws MotionFileException {
        this.getUp = T1GetUp.load(motionDir);
        this.unum = unum;
        this.world = new MjWorld(team, field);
        this.behaviour = new MjBehaviour(field, unum, MjBehaviour.Config.DEFAULT);
        this.talk = new MjTeamTalk(key, team, unum, field, world, behaviour::keeperHasBall, touch::barred);
    }

    /** The double-touch rule as this player keeps it. */
    private final MjTouchRule touch = new MjTouchRule();
    /** Ours: a team-mate's report this near the ball (its kick stance is 0.34 m), heard within MATE_FRESH_S, has played it. */
    static final double MATE_AT_BALL_M = 0.45, MATE_FRESH_S = 1.0;
    /** Ours: our torso moving this far in one cycle, with no beam allowed, is the referee dropping us on the touch line. */
    static final double MOVED_M = 1.5;
    private long refereeMoves;

    /** The reply to one server message. */
    public String update(String message) {
        cycles++;
        MjPerception p;
        try {
            p = parser.parse(message);
        } catch (MalformedMessageException e) {
            if (++malformed <= MALFORMED_LOGGED) LOG.warning("skipped a malformed message (" + e.getMessage() + ")");
            return last;
        }
        if (p.quat() != null && !unitQuaternion(p.quat())) {
            // a zero or non-finite torso quaternion would turn every attitude and position into NaN joint commands
            if (++malformed <= MALFORMED_LOGGED) LOG.warning("skipped a message whose torso quaternion is not a rotation: " + java.util.Arrays.toString(p.quat()));
            return last;
        }
        var before = world.self();
        world.update(p);
        if (before != null && world.self() != null && !world.beamAllowed() && before.position().distanceTo(world.self().position()) > MOVED_M) {
            refereeMoves++;
            LOG.info(String.format(java.util.Locale.ROOT, "moved by the referee %d at %.2f s in %s: %s -> %s, the ball believed at %s",
                    refereeMoves, world.time(), world.playMode(), before, world.self(), world.ball()));
        }
        if (p.quat() != null && p.gyro() != null) {
            double[] rp = T1Model.rollPitch(p.quat());
            gait.feedback(rp[0], rp[1], Math.toRadians(p.gyro()[0]), Math.toRadians(p.gyro()[1]));
        }
        byte[] say = talk.step(p);
        touch.update(world, kick.active() || pendingKick != null, world.otherAtBall(MjTouchRule.OTHER_AT_BALL_M)
                || talk.mateAtBall(world.ball(), MATE_AT_BALL_M, MATE_FRESH_S, world.time()));
        if (touch.barred()) pendingKick = null;   // its one touch was the push on the way: no kick after it
        boolean nearest = world.self() != null && world.ball() != null && talk.nearestToBall(world.self(), world.ball(), world.time());
        MjBehaviour.Intent intent = behaviour.decide(world, talk.order(), nearest, touch.barred());
        List<JointCommand> joints = motion(intent, p);
        for (JointCommand j : joints) actions.joint(j.actuator(), j.qDeg(), j.dqDeg(), j.kp(), j.kd(), j.tau());
        String reply = actions.build();
        last = reply;   // what a malformed message is answered with: never a say again (it would be a replay)
        if (say != null) reply = reply + actions.say(say).build();
        if (intent.beam() != null) {
            beams++;
            int side = world.side();
            // The server puts x on our side itself and turns the right team by 180° (soccer_sim.py beam_agent),
            // but takes y as a world y: our own-frame y is its negative for the right team.
            reply = MjActions.beam(intent.beam().x(), intent.beam().y() * side, intent.beam().thetaDeg()) + reply;
        }
        return reply;
    }

    static boolean unitQuaternion(double[] q) {
        double n = 0;
        for (double v : q) n += v * v;
        return Double.isFinite(n) && Math.abs(n - 1) < 0.1;
    }

    /** Longest wait for the gait's feet to come together before a kick, s; then the kick is dropped. */
    static final double KICK_WAIT_S = 1.0;
    /**
     * Forward command while stepping on the spot before a kick, m/s: the gait creeps forward at 0, and its steps
     * pushed the ball about 0.15 m before the kick (MjKickTest, 2026-12-04: a missed kick and, in a game, a
     * double-touch free kick); -0.1 left it in place (at most 5 mm in 3 runs), -0.05 still pushed it 6 cm.
     */
    static final double WAIT_VX = -0.1;
    /**
     * Still between the feet coming together and the kick, s: the bench kicks after 2.5 s of standing and stood in
     * 10 of 10; straight from the stepping gait the forward fell during the kick in MjKickTest (2026-12-04).
     */
    static final double KICK_SETTLE_S = 0.5;
    /**
     * Still after a kick, s: the torso still sways when the kick ends, and walking at once fell 0.9 s after it in
     * MjKickTest (2026-12-04); the bench stands after its kicks and stood.
     */
    static final double STAND_AFTER_KICK_S = 1.0;

    /**
     * This cycle's joint commands. Stand still only while the referee lets robots beam (or when fallen); in play the
     * gait keeps stepping, also on the spot (a walking T1 switched straight to the still pose fell over the ball:
     * seen in MjTeamTest). A kick plays to its end (or until a fall); it starts from the stand pose, so it waits,
     * stepping on the spot (at WAIT_VX), for a step's end with the feet back at their stance (the gait's pose is
     * then about the stand pose), at most KICK_WAIT_S, and then stands KICK_SETTLE_S.
     */
    private List<JointCommand> motion(MjBehaviour.Intent intent, MjPerception p) {
        if (!world.beamAllowed() && p.quat() != null) {
            long before = getUp.getUps();
            List<JointCommand> g = getUp.update(p.quat(), p.gyro(), a -> measuredDeg(p, a), world.time());
            if (getUp.getUps() > before)
                LOG.info(String.format(java.util.Locale.ROOT, "get-up %d (%s) at %.2f s", getUp.getUps(), getUp.playing(), world.time()));
            if (g != null) {
                kick.stop();
                pendingKick = null;
                settleUntil = 0;
                standUntil = world.time() + STAND_AFTER_GETUP_S;
                return g;
            }
        }
        if (world.beamAllowed() || !world.upright()) {
            kick.stop();
            pendingKick = null;
            settleUntil = 0;
            return gait.stand();
        }
        if (kick.active()) {
            List<JointCommand> j = kick.next();
            if (!kick.active()) {
                standUntil = world.time() + STAND_AFTER_KICK_S;
                LOG.info(String.format(java.util.Locale.ROOT, "kick %d ended at %.2f s in %s, the ball believed at %s", kicks, world.time(),
                        world.playMode(), world.ball()));
            }
            return j;
        }
        if (world.time() < standUntil) return gait.stand();   // then the gait starts afresh from the stand pose
        if (intent.kick() != null && pendingKick == null) {
            pendingKick = intent.kick();
            pendingSince = world.time();
        }
        if (pendingKick == null) return gait.next(intent.vx(), intent.vy(), intent.turnDegPerS());
        if (settleUntil > 0) {   // feet together: stand still a moment, then kick
            if (world.time() < settleUntil) return gait.stand();
            settleUntil = 0;
            MjBehaviour.Foot foot = pendingKick;
            pendingKick = null;
            var refused = kick.start(foot == MjBehaviour.Foot.LEFT, world.upright());
            if (refused.isEmpty()) {
                kicks++;
                LOG.info(String.format(java.util.Locale.ROOT, "kick %d (%s foot) at %.2f s from %s, the ball believed at %s", kicks,
                        foot == MjBehaviour.Foot.LEFT ? "left" : "right", world.time(), world.self(), world.ball()));
                return kick.next();
            }
            kicksRefused++;
            LOG.fine("kick refused: " + refused.get());
        } else if (feetTogether()) {
            settleUntil = world.time() + KICK_SETTLE_S;
            return gait.stand();
        } else if (world.time() - pendingSince > KICK_WAIT_S) {
            pendingKick = null;
        }
        return gait.next(WAIT_VX, 0, 0);
    }

    /** Still after a get-up, s, before the gait walks: the bench's get-up trial stands 3 s after it (motion/README.md). */
    static final double STAND_AFTER_GETUP_S = 1.0;

    /** A joint's measured angle in the perception, degrees, by actuator name (0 when the perception lacks it). */
    public static double measuredDeg(MjPerception p, String actuator) {
        double[] v = p.joints().get(T1Joints.byActuator(actuator).perceptor());
        return v == null ? 0 : v[0];
    }

    private boolean feetTogether() {
        double[] lift = gait.lifts(), off = gait.footOffsets();
        double most = 0;
        for (int k : new int[]{0, 1, 3, 4}) most = Math.max(most, Math.abs(off[k]));
        return lift[0] < 1e-3 && lift[1] < 1e-3 && most < 0.02 && Math.abs(off[2]) < 0.05 && Math.abs(off[5]) < 0.05;
    }

    /** Times the referee dropped this player on the touch line (a jump of the torso in play), and times the double-touch rule barred it. */
    public long refereeMoves() { return refereeMoves; }
    public long touchBars() { return touch.bars(); }
    /** The double-touch rule bars this player from the ball now. */
    public boolean barred() { return touch.barred(); }

    /** Kicks started and kicks the motion refused, so far. */
    public long kicks() { return kicks; }
    public long kicksRefused() { return kicksRefused; }
    /** Get-ups started so far, and of those the retries (the one before ended still down). */
    public long getUps() { return getUp.getUps(); }
    public long getUpRetries() { return getUp.retries(); }

    public int unum() { return unum; }
    public MjWorld world() { return world; }
    public MjBehaviour behaviour() { return behaviour; }
    public long cycles() { return cycles; }
    public long malformed() { return malformed; }
    public long beams() { return beams; }
    /** Team-mates' reports heard and accepted so far. */
    public long heardFromMates() { return talk.accepted(); }
    /** The team channel's end: its rounds on the goalkeeper, its orders on a field player (counts for tests and logs). */
    public phalanx.agent.team.TeamChannel channel() { return talk.channel(); }
}

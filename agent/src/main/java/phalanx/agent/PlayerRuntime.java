package phalanx.agent;

import phalanx.agent.team.TeamChannel;

import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.roboviz.BeliefDrawing;
import phalanx.agent.roboviz.PlanDrawing;
import phalanx.coordination.TeamPlan;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Pose2;
import phalanx.motion.control.HeadServo;
import phalanx.motion.control.JointVelocities;

import java.util.logging.Logger;

/**
 * One cycle of a player, without the socket: message bytes in, reply text out —
 * sense (parse) → model (beliefs) → decide (team channel, brain) → act (beam, motion, head, say).
 * A malformed message or a failure while thinking is logged and answered with a bare syn.
 */
public final class PlayerRuntime {
    private static final Logger LOG = Logger.getLogger(PlayerRuntime.class.getName());

    private final PlayerOptions options;
    private final PlayerParts parts;
    private final PerceptionParser parser = new PerceptionParser();
    private final EffectorMessage out = new EffectorMessage();
    private final BeamPolicy beams;
    private PlayMode playMode;
    private double gameTime;
    private final FallLog fallLog = new FallLog();
    private long cycles;
    private long malformed;
    private TeamPlan drawnPlan;

    public PlayerRuntime(PlayerOptions options, PlayerParts parts) {
        this.options = options;
        this.parts = parts;
        this.beams = new BeamPolicy(parts.field(), parts.config().coordination(), parts.config().agent().kickOff());
    }

    /** The reply to one perceptor message (the payload of one frame), ending in (syn). */
    public CharSequence update(byte[] message, int length) {
        cycles++;
        out.reset();
        if (cycles == 1) return EffectorMessage.init(options.unum(), options.team());
        Perception p;
        try {
            p = parser.parse(message, 0, length);
        } catch (MalformedMessageException e) {
            malformed++;
            if (malformed <= 10 || malformed % 1000 == 0) LOG.warning("cycle " + cycles + ": malformed message skipped (" + e.getMessage() + ")");
            return out.syn().text();
        }
        try {
            think(p);
        } catch (RuntimeException e) {
            // A bug in one decision must not cost the connection: log it, send nothing but syn.
            LOG.severe("cycle " + cycles + ": thinking failed: " + e);
            out.reset();
        }
        return out.syn().text();
    }

    public long cycles() { return cycles; }

    /** What the belief store saw and skipped so far (logged with the think times, for match reviews). */
    public phalanx.localization.belief.BeliefStats beliefStats() { return parts.beliefs().stats(); }
    public long malformed() { return malformed; }
    public PlayMode playMode() { return playMode; }

    private void think(Perception p) {
        if (p.gameState() != null) {
            playMode = p.gameState().playMode();
            gameTime = p.gameState().gameTime();
            parts.playMode(playMode);
        }
        Situation.MotionStatus motion = parts.motionStatus();
        parts.beliefs().bodyBusy(!motion.idle());
        WorldBelief belief = parts.beliefs().update(p);                                                  // model
        fallLog.update(belief.fall(), gameTime);
        Situation s = new Situation(p.time(), cycles, playMode, gameTime, belief, parts.field(), p.joints(), motion);
        int unum = belief.unum() > 0 ? belief.unum() : options.unum();
        PlayerParts.Role role = parts.role(unum);
        String say = role == null ? null : role.channel().step(p.time(), playMode, p.hears(), belief);
        if (role != null) {
            for (TeamChannel.HeardBall h : role.channel().heardBalls()) parts.beliefs().teamBall(h.sender(), h.ball(), h.time());
        }
        Decision d = role == null ? Decision.of(null, null) : role.brain().decide(s, role.channel());          // decide

        Pose2 beam = beams.beam(playMode, p.time(), unum);                                                  // act
        if (beam != null) {
            out.beam(beam.x(), beam.y(), beam.thetaDeg());
            parts.beliefs().forgetPose();
        }
        JointVelocities v = parts.body().step(p, d.move());
        parts.beliefs().odometry(parts.body().odometry().forward(), parts.body().odometry().left(), parts.body().odometry().turnDeg());
        appendWithHead(v, p, d);
        if (say != null) out.say(say);
        if (parts.draw().on()) draw(belief, role, unum);
    }

    private void draw(WorldBelief belief, PlayerParts.Role role, int unum) {
        BeliefDrawing.draw(parts.draw(), belief, role == null ? null : role.brain().target(), options.team(), unum);
        TeamPlan plan = role == null ? null : role.channel().lastPlan();
        if (plan != null && plan != drawnPlan) {
            PlanDrawing.draw(parts.draw(), plan, belief.side(), options.team());
            drawnPlan = plan;
        }
    }

    /**
     * Appends the body's commands with the head following the decision's target ({@link HeadServo});
     * motion files leave the head alone.
     */
    private void appendWithHead(JointVelocities v, Perception p, Decision d) {
        if (!p.joints().has(Joint.HJ1) || !p.joints().has(Joint.HJ2)) {
            v.appendTo(out);
            return;
        }
        v.appendTo(out, HeadServo.velocity(d.head().yawDeg(), p.joints().degrees(Joint.HJ1)),
                HeadServo.velocity(d.head().pitchDeg(), p.joints().degrees(Joint.HJ2)));
    }
}

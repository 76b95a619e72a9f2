package phalanx.agent;

import phalanx.agent.act.Locomotion;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.roboviz.BeliefDrawing;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.ServerConnection;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.field.Pose2;
import phalanx.motion.control.JointVelocities;

import java.io.IOException;
import java.util.logging.Logger;

/**
 * The player's cycle, sense → model → decide → act, every cycle without fail: a malformed message
 * is logged and answered with a bare {@code (syn)}, and a failure inside one cycle's thinking is
 * logged and costs only that cycle. The first message after {@code (scene)} is answered with
 * {@code (init)}.
 */
public final class ThinkLoop {
    private static final Logger LOG = Logger.getLogger(ThinkLoop.class.getName());
    /** Head P-controller gain, 1/s: 8/s x 20 ms closes 16 % of the error a cycle, stable with 1 cycle of latency. */
    private static final double HEAD_GAIN = 8.0;

    /** How the loop ended. */
    public record Outcome(long cycles, long malformed, String reason, PlayMode lastPlayMode) {
        public boolean gameOver() { return lastPlayMode == PlayMode.GAME_OVER; }
    }

    private final ServerConnection connection;
    private final PlayerOptions options;
    private final PlayerParts parts;
    private final PerceptionParser parser = new PerceptionParser();
    private final EffectorMessage out = new EffectorMessage();
    private final BeamPolicy beams;
    private final ThinkTimes times = new ThinkTimes();
    private PlayMode playMode;
    private double gameTime;
    private long cycles;

    public ThinkLoop(ServerConnection connection, PlayerOptions options, PlayerParts parts) {
        this.connection = connection;
        this.options = options;
        this.parts = parts;
        this.beams = new BeamPolicy(parts.field(), phalanx.coordination.CoordinationConfig.THESIS);
    }

    /** Runs until the connection ends; never throws for bad input. */
    public Outcome run() {
        long malformed = 0;
        FrameReader in = connection.reader();
        try {
            connection.send(EffectorMessage.scene(options.robotType()));
            while (true) {
                in.next();
                long start = System.nanoTime();
                cycles++;
                out.reset();
                if (cycles == 1) {
                    connection.send(EffectorMessage.init(options.unum(), options.team()));
                    continue;
                }
                if (cycles == 2) LOG.info("in the game as " + options.team() + " " + options.unum());
                Perception p;
                try {
                    p = parser.parse(in.buffer(), 0, in.length());                  // sense
                } catch (MalformedMessageException e) {
                    malformed++;
                    if (malformed <= 10 || malformed % 1000 == 0) {
                        LOG.warning("cycle " + cycles + ": malformed message skipped (" + e.getMessage() + ")");
                    }
                    connection.send(out.syn().text());
                    continue;
                }
                try {
                    think(p);
                } catch (RuntimeException e) {
                    // A bug in one decision must not cost the connection: log it, send nothing but syn.
                    LOG.severe("cycle " + cycles + ": thinking failed: " + e);
                    out.reset();
                }
                connection.send(out.syn().text());
                times.add(System.nanoTime() - start);
            }
        } catch (ConnectionClosedException e) {
            return end(new Outcome(cycles, malformed, "server closed the connection: " + e.getMessage(), playMode));
        } catch (IOException e) {
            return end(new Outcome(cycles, malformed, "connection lost: " + e.getMessage(), playMode));
        }
    }

    private Outcome end(Outcome o) {
        LOG.info(times.summary());
        return o;
    }

    /** One cycle after parsing: model, decide, act. */
    private void think(Perception p) {
        if (p.gameState() != null) {
            playMode = p.gameState().playMode();
            gameTime = p.gameState().gameTime();
            parts.playMode(playMode);
        }
        WorldBelief belief = parts.beliefs().update(p);                                          // model
        Situation s = new Situation(p.time(), cycles, playMode, gameTime, belief, parts.field(), p.joints(), parts.motionStatus());
        int unum = belief.unum() > 0 ? belief.unum() : options.unum();
        PlayerParts.Role role = parts.role(unum);
        String say = role == null ? null : role.channel().step(p.time(), playMode, p.hears(), belief);
        Decision d = role == null ? Decision.of(null, null) : role.brain().decide(s, role.channel());  // decide

        Pose2 beam = beams.beam(playMode, p.time(), unum);                       // act
        if (beam != null) {
            out.beam(beam.x(), beam.y(), beam.thetaDeg());
            parts.beliefs().forgetPose();
        }
        JointVelocities v = parts.motion().step(p.time(), p.joints(), Locomotion.request(d.move()));
        v = headTowards(v, p, d);
        v.appendTo(out);
        if (say != null) out.say(say);
        if (parts.draw().on()) BeliefDrawing.draw(parts.draw(), belief, role == null ? null : role.brain().target(), options.team(), unum);
    }

    /** The head follows the decision's target with a P-controller; motion files leave the head alone. */
    private static JointVelocities headTowards(JointVelocities v, Perception p, Decision d) {
        if (!p.joints().has(Joint.HJ1) || !p.joints().has(Joint.HJ2)) return v;
        double yaw = HEAD_GAIN * Math.toRadians(d.head().yawDeg() - p.joints().degrees(Joint.HJ1));
        double pitch = HEAD_GAIN * Math.toRadians(d.head().pitchDeg() - p.joints().degrees(Joint.HJ2));
        return v.with(Joint.HJ1, clamp(yaw)).with(Joint.HJ2, clamp(pitch));
    }

    private static double clamp(double radPerSecond) {
        return Math.max(-6.0, Math.min(6.0, radPerSecond));
    }
}

package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.model.field.Vector2;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * Our kick-off without the taker's foul ({@link AgentConfig.KickOff}, ours). In our KickOff the taker
 * walks to the ball and taps it with slow forward steps, and the partner stands by. The tap turns the
 * mode into PlayOn. From then on the taker leaves the ball alone, and the partner plays it with On Ball.
 * This lasts until the partner has kicked, the hold time is over, or the ball is away from the centre
 * spot. Every other player, and every other moment, is left to the usual choice ({@link #decide}
 * returns null).
 */
public final class KickOffPlay {
    private static final Logger LOG = Logger.getLogger(KickOffPlay.class.getName());

    /** What this player does in our kick-off. */
    public enum Part { TAKER, PARTNER, NONE }

    private final AgentConfig config;
    private final Part part;
    private final WalkToBall walk;
    private final TrackObject track;
    private OnBall onBall;
    private boolean wasOurKickOff;
    private double tapped = Double.NaN;

    public KickOffPlay(AgentConfig config, int unum) {
        this.config = config;
        AgentConfig.KickOff k = config.kickOff();
        this.part = !k.enabled() ? Part.NONE : unum == k.taker() ? Part.TAKER : unum == k.partner() ? Part.PARTNER : Part.NONE;
        this.walk = new WalkToBall(config);
        this.track = TrackObject.ball(config);
    }

    public Part part() { return part; }

    /** True from the tap until the partner has played the ball (or the hold ended). */
    public boolean holding() { return !Double.isNaN(tapped); }

    /** This cycle's decision when the kick-off decides it, else null (the usual choice). */
    public Decision decide(Situation s) {
        if (part == Part.NONE) return null;
        boolean ours = ourKickOff(s);
        if (wasOurKickOff && !ours && s.playMode() == PlayMode.PLAY_ON) {
            tapped = s.gameTime();
            onBall = new OnBall(config);
            LOG.info(String.format(Locale.ROOT, "kick-off: tapped at game time %.2f, %s", s.gameTime(),
                    part == Part.TAKER ? "leaving the ball to the partner" : "playing it"));
        }
        wasOurKickOff = ours;
        if (ours) {
            tapped = Double.NaN;
            if (part == Part.PARTNER) return Decision.of(Move.STAND, track.head(s));
            // The taker: to the ball, then slow forward steps into it; the first touch ends the kick-off.
            return walk.done(s) ? Decision.of(new Move.Walk(0, true), track.head(s)) : walk.decide(s);
        }
        if (!holding()) return null;
        if (s.playMode() != PlayMode.PLAY_ON || s.gameTime() - tapped > config.kickOff().holdSeconds() || ballAway(s)) {
            release(s, "hold over");
            return null;
        }
        if (part == Part.TAKER) return Decision.of(Move.STAND, track.head(s));
        Decision d = onBall.decide(s);
        if (onBall.done(s)) release(s, "partner kicked");
        return d;
    }

    private void release(Situation s, String why) {
        LOG.info(String.format(Locale.ROOT, "kick-off: %s at game time %.2f", why, s.gameTime()));
        tapped = Double.NaN;
        onBall = null;
    }

    /** The ball believed more than releaseDistance from the centre spot (a player has moved it). */
    private boolean ballAway(Situation s) {
        Vector2 ball = Facts.ballGlobal(s, config);
        return ball != null && ball.norm() > config.kickOff().releaseDistance();
    }

    private static boolean ourKickOff(Situation s) {
        PlayMode m = s.playMode();
        if (m != PlayMode.KICK_OFF_LEFT && m != PlayMode.KICK_OFF_RIGHT) return false;
        Side ours = s.belief() == null ? null : s.belief().side();
        return ours != null && m.owner() == ours;
    }
}

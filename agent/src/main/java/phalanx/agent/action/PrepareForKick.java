package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Vector2;

/**
 * 4.6.1 Prepare For Kick: side steps and slow forward steps, until the ball lies in front of the
 * kicking foot (the kick's spot) within the tolerances. Ours: the kicking foot is the one on the
 * ball's side when preparing begins ({@link #choose}), so a ball left of the body needs no side
 * steps across to the right foot; the left foot's spot is the right one's mirror. Sideways first (a forward step with the ball
 * off to the side would push it away), then forward. Ours, beyond the thesis: a ball nearer than
 * the spot's band (at the feet) is not kicked off the shin; the robot steps back first (a side step
 * there would push the ball with the foot), and side-steps away from a ball that stays caught at
 * its feet while it steps back. The forward steps go on until the ball is within
 * {@code toleranceFarX} beyond the spot, not just inside the band: the robot stops where it first
 * accepts the ball, so the far edge would be where every kick is played.
 */
public final class PrepareForKick implements Action {
    private final AgentConfig config;
    private final TrackObject track;
    private boolean left;
    private boolean strong;

    public PrepareForKick(AgentConfig config) {
        this.config = config;
        this.track = TrackObject.ball(config);
    }

    /**
     * Prepares for the strong or the normal kick (each has its spot) with the foot whose spot is nearer
     * the ball now; both are kept until the next call.
     */
    public void choose(Situation s, boolean strongKick) { choose(s, strongKick, false); }

    /** The same for the quick kick's spot when {@code quickKick}. */
    public void choose(Situation s, boolean strongKick, boolean quickKick) {
        Vector2 ball = Facts.ball(s, config);
        left = ball != null && ball.y() > 0;
        strong = strongKick;
        quick = quickKick;
    }

    /** True when preparing for the quick kick. */
    public boolean quick() { return quick; }

    /** True when the kick is to be played with the left foot. */
    public boolean leftFoot() { return left; }

    /** True when preparing for the strong kick. */
    public boolean strong() { return strong; }

    @Override
    public Decision decide(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null || ready(ball)) return Decision.of(Move.STAND, track.head(s));
        AgentConfig.Kick k = config.kick();
        if (ball.x() < k.spotX(strong, quick) - k.toleranceX()) {
            if (Double.isNaN(backSince)) { backSince = s.gameTime(); backBallX = ball.x(); }
            // A ball caught at the feet comes back with each step: in a game against UT Austin Villa (session 24) a
            // player stepped back 12 s with the ball 8 cm in front of it and took it 3 m toward our goal. A side step
            // away from the ball leaves it behind.
            if (s.gameTime() - backSince > STUCK_SECONDS && ball.x() < backBallX + STUCK_GAIN)
                return Decision.of(new Move.SideStep(ball.y() < 0), track.head(s));
            return Decision.of(new Move.StepBack(), track.head(s));
        }
        backSince = Double.NaN;
        double ey = ball.y() - k.spotY(strong, quick, left);
        if (Math.abs(ey) > k.toleranceY()) return Decision.of(new Move.SideStep(ey > 0), track.head(s));
        return Decision.of(new Move.Walk(0, true), track.head(s));
    }

    /** Stepping back this long, game s, ... */
    private static final double STUCK_SECONDS = 1.0;
    /** ... with the ball not this much farther than when it began (m), the ball is caught at the feet. */
    private static final double STUCK_GAIN = 0.03;
    private double backSince = Double.NaN, backBallX;
    private boolean quick;

    @Override
    public boolean done(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        return ball != null && ready(ball);
    }

    private boolean ready(Vector2 ball) {
        AgentConfig.Kick k = config.kick();
        double ex = ball.x() - k.spotX(strong, quick);
        return ex >= -k.toleranceX() && ex <= k.toleranceFarX() && Math.abs(ball.y() - k.spotY(strong, quick, left)) <= k.toleranceY();
    }
}

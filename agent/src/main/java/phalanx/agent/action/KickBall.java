package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * One kick with either foot, played once to its end (On Ball's last step). Call {@link #start} when the
 * ball is in place; {@link #done} turns true when the motion has ended.
 */
public final class KickBall implements Action {
    private final OneShot play;
    private final TrackObject track;
    private boolean strong;
    private boolean left;
    private boolean quick;

    public KickBall(AgentConfig config) {
        this.play = new OneShot(config.kick().oneShotTimeout());
        this.track = TrackObject.ball(config);
    }

    /** Begins a kick this cycle. */
    public void start(Situation s, boolean strongKick, boolean leftFoot) { start(s, strongKick, leftFoot, false); }

    /** Begins a kick this cycle, the quick kick when {@code quickKick}. */
    public void start(Situation s, boolean strongKick, boolean leftFoot, boolean quickKick) {
        strong = strongKick;
        left = leftFoot;
        quick = quickKick;
        play.start(s);
    }

    @Override
    public Decision decide(Situation s) {
        if (!play.active() || play.finished(s)) return Decision.of(Move.STAND, track.head(s));
        return Decision.of(play.requesting() ? new Move.Kick(strong, left, quick) : Move.STAND, track.head(s));
    }

    @Override
    public boolean done(Situation s) { return !play.active(); }
}

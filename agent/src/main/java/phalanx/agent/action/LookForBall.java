package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.localization.belief.WorldBelief;

/**
 * 4.6.1 Look For Ball: turn the body while scanning until the ball is in view. It turns toward the
 * side where the ball was last seen (left when it never was).
 */
public final class LookForBall extends SearchAction {

    public LookForBall(AgentConfig config) { super(config, new Scan(config)); }

    @Override
    protected Move searching(Situation s) { return new Move.Turn(lastSeenLeft(s), config.walk().gainMax()); }

    @Override
    protected Decision found(Situation s) { return Decision.of(Move.STAND, TrackObject.ball(config).head(s)); }

    @Override
    public boolean done(Situation s) { return Facts.ballInView(s, config) != null; }

    private static boolean lastSeenLeft(Situation s) {
        WorldBelief b = s.belief();
        if (b == null || b.ballRelative() == null || !(b.ballRelative().y() < 0)) return true;
        return false;
    }
}

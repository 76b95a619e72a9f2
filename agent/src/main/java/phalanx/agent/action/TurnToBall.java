package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Vector2;

/**
 * 4.6.1 Turn To Ball: turn the body toward the ball while tracking it. Applicable only when the
 * ball is known; otherwise it stands and pans the head.
 */
public final class TurnToBall implements Action {
    private final AgentConfig config;
    private final TrackObject track;

    public TurnToBall(AgentConfig config) {
        this.config = config;
        this.track = TrackObject.ball(config);
    }

    @Override
    public Decision decide(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null || done(s)) return Decision.of(Move.STAND, track.head(s));
        return Decision.of(Steer.turn(Facts.bearing(ball), config.walk()), track.head(s));
    }

    @Override
    public boolean done(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        return ball != null && Math.abs(Facts.bearing(ball)) <= config.walk().ballTurnToleranceDeg();
    }
}

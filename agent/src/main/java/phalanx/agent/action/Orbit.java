package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Vector2;

/**
 * Turns the body's heading around a ball lying in front of it, with side steps and turns only
 * (the motions Prepare For Kick may use): a side step away from the wanted turn moves the body
 * around the ball, a turn toward the ball puts it back in front. Used by On Ball to align with the
 * goal and by Dribble to align with its direction. The thesis says "aligns itself" without saying
 * how; this keeps the ball close all the way.
 */
final class Orbit {
    /** Beyond this bearing the ball is put back in front before the next side step. */
    static final double BALL_BEARING_DEG = 15;

    private final AgentConfig config;
    private final TrackObject track;

    Orbit(AgentConfig config) {
        this.config = config;
        this.track = TrackObject.ball(config);
    }

    /** One step toward a heading {@code errorDeg} away (+ left) with the ball at {@code ball}. */
    Decision step(Situation s, Vector2 ball, double errorDeg) {
        double b = Facts.bearing(ball);
        if (Math.abs(b) > BALL_BEARING_DEG) return Decision.of(Steer.turn(b, config.walk()), track.head(s));
        // Heading to turn left: the body must go round the ball clockwise, i.e. step to the right.
        return Decision.of(new Move.SideStep(errorDeg < 0), track.head(s));
    }
}

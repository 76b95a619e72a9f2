package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Vector2;

/**
 * 4.6.2 Walk To Ball: turn to the ball, walk to it, slow down near it, stop close enough to kick.
 * Distances are ground distances: the belief store already projects the camera's view onto the
 * ground with the camera height from the legs' forward kinematics (the thesis's Figure 4.13). The
 * body aims at a point beside the ball so that it arrives with the ball in front of the right foot.
 * Obstacles are avoided until the last metre (a player at the ball must not turn us away from it).
 * Without a ball it looks for one.
 */
public final class WalkToBall implements Action {
    /** Within this the way goes straight to the ball, not around players. */
    private static final double AVOID_BEYOND = 1.0;

    private final AgentConfig config;
    private final AvoidObstacles avoid;
    private final LookForBall look;
    private final TrackObject track;

    public WalkToBall(AgentConfig config) {
        this.config = config;
        this.avoid = new AvoidObstacles(config);
        this.look = new LookForBall(config);
        this.track = TrackObject.ball(config);
    }

    @Override
    public Decision decide(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null) return look.decide(s);
        AgentConfig.Walk w = config.walk();
        double d = ball.norm();
        if (d <= w.ballStopDistance()) return Decision.of(Move.STAND, track.head(s));
        Vector2 aim = new Vector2(ball.x(), ball.y() - config.kick().spotY());
        Vector2 way = d > AVOID_BEYOND ? avoid.route(s, aim) : aim;
        return Decision.of(Steer.toward(Facts.bearing(way), d < w.slowdownDistance(), w), track.head(s));
    }

    @Override
    public boolean done(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        return ball != null && ball.norm() <= config.walk().ballStopDistance();
    }
}

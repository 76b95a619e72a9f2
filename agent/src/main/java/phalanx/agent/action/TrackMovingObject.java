package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * 4.6.1 Track Moving Object on the ball: Track Object plus the ball's direction and speed. The two
 * sets of five observations live in the belief store ({@code WorldBelief.ballVelocity}, own frame);
 * here they are turned into the body frame, and the head leads a moving ball slightly so the
 * latency of vision does not leave it behind.
 */
public final class TrackMovingObject implements HeadControl {
    private final AgentConfig config;
    private final PanHead pan;

    public TrackMovingObject(AgentConfig config) {
        this.config = config;
        this.pan = new PanHead(config);
    }

    @Override
    public HeadTarget head(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null) return pan.head(s);
        Vector2 v = relativeVelocity(s);
        Vector2 aim = v == null ? ball : ball.plus(v.times(config.head().leadSeconds()));
        return TrackObject.toward(aim, TrackObject.BALL_RADIUS, s, config);
    }

    /** The ball's velocity in the body frame (+x forward, +y left), m/s; null when not tracked or without a self pose. */
    public Vector2 relativeVelocity(Situation s) {
        Vector2 v = Facts.ballVelocity(s);
        Pose2 self = Facts.self(s, config);
        return v == null || self == null ? null : v.rotate(-self.thetaDeg());
    }
}

package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.JointAngles;
import phalanx.model.field.Vector2;
import phalanx.model.robot.CameraHeight;

/**
 * 4.6.1 Track Object: points the camera at an object on the ground so it stays in the centre of the
 * view: yaw from the body-relative direction, pitch from the ground distance and the camera height
 * (forward kinematics of the legs, 4.6.2 Walk to Ball). The ball by default, or a fixed point of the
 * own frame. When the object is not known it pans (the thesis's action is not applicable then).
 */
public final class TrackObject implements HeadControl {
    /** The ball's radius (naosoccersim.rb BallRadius): its centre is this high. */
    public static final double BALL_RADIUS = 0.042;

    private final AgentConfig config;
    private final Vector2 point;          // own frame; null = the ball
    private final double height;
    private final PanHead pan;

    private TrackObject(AgentConfig config, Vector2 point, double height) {
        this.config = config;
        this.point = point;
        this.height = height;
        this.pan = new PanHead(config);
    }

    /** Tracks the ball. */
    public static TrackObject ball(AgentConfig config) { return new TrackObject(config, null, BALL_RADIUS); }

    /** Tracks a point of the own frame at the given height (needs a self belief). */
    public static TrackObject point(AgentConfig config, Vector2 global, double height) {
        return new TrackObject(config, global, height);
    }

    @Override
    public HeadTarget head(Situation s) {
        Vector2 rel = point == null ? Facts.ball(s, config) : Facts.relative(s, config, point);
        return rel == null ? pan.head(s) : toward(rel, height, s, config);
    }

    /** The neck angles that centre a body-relative ground point at the given height. */
    public static HeadTarget toward(Vector2 relative, double objectHeight, Situation s, AgentConfig c) {
        if (relative == null || !relative.isFinite()) return HeadTarget.STRAIGHT;
        double yaw = relative.angleDeg();
        double pitch = -Math.toDegrees(Math.atan2(cameraHeight(s, c) - objectHeight, relative.norm()));
        return new HeadTarget(yaw, pitch);
    }

    /** Camera height from the leg joints; the standing height when a joint reading is missing. */
    static double cameraHeight(Situation s, AgentConfig c) {
        JointAngles j = s.joints();
        double h = j == null ? Double.NaN : CameraHeight.of(c.head().legs(), j);
        if (Double.isFinite(h) && h > 0.2 && h < 1.0) return h;
        return c.head().legs().standingTorsoHeight() + c.head().legs().cameraAboveTorso();
    }
}

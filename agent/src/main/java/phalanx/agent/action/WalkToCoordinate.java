package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * 4.6.2 Walk To Coordinate: go to (x, y) of the own frame through Avoid Obstacles, slowing down
 * near it, then turn in place to θ. Direction and distance are recomputed every cycle. Once at the
 * position it only turns, until pushed twice the tolerance away (no dithering on the spot). The
 * thesis writes φ = atan2(x_t − x_a, y_t − y_a); in our frame (θ counter-clockwise from +x) that
 * is atan2(y_t − y_a, x_t − x_a). Without a usable self pose it turns to localize first.
 */
public final class WalkToCoordinate implements Action {
    private final AgentConfig config;
    private final AvoidObstacles avoid;
    private final TurnToLocalize localize;
    private final Gaze gaze;
    private Vector2 target;
    private double thetaDeg;
    private boolean arrived;

    public WalkToCoordinate(AgentConfig config, double x, double y, double thetaDeg) {
        this.config = config;
        this.avoid = new AvoidObstacles(config);
        this.localize = new TurnToLocalize(config);
        this.gaze = new Gaze(config);
        this.target = Vector2.ZERO;
        target(x, y, thetaDeg);
    }

    /** A new target; keeps "arrived" when it moved less than the tolerance. Non-finite values are ignored. */
    public void target(double x, double y, double theta) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(theta)) return;
        Vector2 t = new Vector2(x, y);
        if (t.distanceTo(target) > config.walk().positionTolerance()) arrived = false;
        target = t;
        thetaDeg = theta;
    }

    public Pose2 target() { return new Pose2(target.x(), target.y(), thetaDeg); }

    @Override
    public Decision decide(Situation s) {
        Pose2 self = Facts.self(s, config);
        if (self == null) return localize.decide(s);
        AgentConfig.Walk w = config.walk();
        Vector2 rel = self.toRelative(target);
        double d = rel.norm();
        arrived = d <= (arrived ? 2 : 1) * w.positionTolerance();
        if (!arrived) {
            Vector2 way = avoid.route(s, rel);
            return Decision.of(Steer.toward(Facts.bearing(way), d < w.slowdownDistance(), w), gaze.head(s));
        }
        double turn = Angles.difference(thetaDeg, self.thetaDeg());
        Move m = Math.abs(turn) <= w.thetaToleranceDeg() ? Move.STAND : Steer.turn(turn, w);
        return Decision.of(m, gaze.head(s));
    }

    @Override
    public boolean done(Situation s) {
        Pose2 self = Facts.self(s, config);
        if (self == null) return false;
        return self.position().distanceTo(target) <= (arrived ? 2 : 1) * config.walk().positionTolerance()
                && Math.abs(Angles.difference(thetaDeg, self.thetaDeg())) <= config.walk().thetaToleranceDeg();
    }
}

package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * 4.6.2 Walk To Direction: walk along a direction of the own frame until told otherwise. Below 7°
 * of heading error a leaning walk, above it a turn first (one motion at a time: the thesis's turn
 * "in parallel to" the walk becomes turn-then-walk). The way goes through Avoid Obstacles: the
 * direction is a point a few metres ahead, and a blocked way bends to an escape way point.
 * Without a self pose it turns to localize first.
 */
public final class WalkToDirection implements Action {
    /** How far ahead the direction is looked at for obstacles (beyond Avoid Obstacles' 2 m range). */
    private static final double LOOK_AHEAD = 3.0;

    private final AgentConfig config;
    private final AvoidObstacles avoid;
    private final TurnToLocalize localize;
    private final Gaze gaze;
    private double directionDeg;

    public WalkToDirection(AgentConfig config, double directionDeg) {
        this.config = config;
        this.avoid = new AvoidObstacles(config);
        this.localize = new TurnToLocalize(config);
        this.gaze = new Gaze(config);
        direction(directionDeg);
    }

    /** A new direction (own frame, degrees); a non-finite one is ignored. */
    public void direction(double deg) { if (Double.isFinite(deg)) directionDeg = deg; }

    public double direction() { return directionDeg; }

    @Override
    public Decision decide(Situation s) {
        Pose2 self = Facts.self(s, config);
        if (self == null) return localize.decide(s);
        double error = Angles.difference(directionDeg, self.thetaDeg());
        Vector2 way = avoid.route(s, Vector2.polar(LOOK_AHEAD, error));
        return Decision.of(Steer.toward(Facts.bearing(way), false, config.walk()), gaze.head(s));
    }
}

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
 * 4.6.2 Dribble Ball To Direction: Walk To Direction with the ball kept in front of the feet. Away
 * from the ball it walks to it; at the ball with the heading off by more than twice Walk To
 * Direction's 7° it goes round the ball (side steps and turns); otherwise it walks on, leaning
 * toward the heading and toward the ball so the ball stays between the feet. A ball within Walk To
 * Ball's stopping distance but beside or behind the feet is brought in front with a side step or a
 * step back (Walk To Ball would only stand there: a player stood 80 s beside the ball on an empty
 * field, docs/matches.md). The thesis calls its
 * own version "not fully functional"; so is this one until it is tuned in the server.
 */
public final class DribbleBallToDirection implements Action {
    /** The ball counts as "at the feet" within this ahead ... */
    private static final double AT_FEET_AHEAD = 0.35;
    /** ... and this to either side. */
    private static final double AT_FEET_SIDE = 0.15;
    /** A ball nearer than this ahead (or behind) is stepped back from, not side-stepped to. */
    private static final double BEHIND = 0.08;
    /** Lateral ball offset that gives full lean toward it. */
    private static final double FULL_LEAN_OFFSET = 0.1;

    private final AgentConfig config;
    private final WalkToBall walk;
    private final TurnToLocalize localize;
    private final Orbit orbit;
    private final TrackObject track;
    private double directionDeg;

    public DribbleBallToDirection(AgentConfig config, double directionDeg) {
        this.config = config;
        this.walk = new WalkToBall(config);
        this.localize = new TurnToLocalize(config);
        this.orbit = new Orbit(config);
        this.track = TrackObject.ball(config);
        direction(directionDeg);
    }

    /** A new direction (own frame, degrees); a non-finite one is ignored. */
    public void direction(double deg) { if (Double.isFinite(deg)) directionDeg = deg; }

    public double direction() { return directionDeg; }

    @Override
    public Decision decide(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null) return walk.decide(s);
        if (!atFeet(ball)) {
            Decision omni = toTheBall(s);
            if (omni != null) return omni;
            if (ball.norm() > config.walk().ballStopDistance()) return walk.decide(s);
            if (ball.x() < BEHIND) return Decision.of(new Move.StepBack(), track.head(s));
            return Decision.of(new Move.SideStep(ball.y() > 0), track.head(s));
        }
        Pose2 self = Facts.self(s, config);
        if (self == null) return localize.decide(s);
        double e = Angles.difference(directionDeg, self.thetaDeg());
        if (Math.abs(e) > 2 * config.walk().leanBelowDeg()) return orbit.step(s, ball, e);
        double lean = e / config.walk().leanBelowDeg() + ball.y() / FULL_LEAN_OFFSET;
        return Decision.of(new Move.Walk(Facts.clamp(lean, -1, 1), false), track.head(s));
    }

    /**
     * Ours (session 24): with a fresh self pose and the approach on (AgentConfig.Approach), a ball away from the feet is
     * walked to with the omnidirectional walk, to the point behind it along the dribble's direction, turning on the way
     * ({@link ApproachBall#behind}). Walk To Ball turned on the spot and then walked slowly within 0.6 m: in a game against
     * UT Austin Villa On Ball spent 106 s dribbling with the ball 0.4-1 m away, 40 s of it turning on the spot, while an
     * opponent stood at the ball and lined up its kick. Null: the thesis's way.
     */
    private Decision toTheBall(Situation s) {
        Pose2 self = Facts.self(s, config);
        Vector2 ball = Facts.ballGlobal(s, config);
        if (!config.approach().enabled() || self == null || ball == null || !Facts.selfLocalized(s, config)) return null;
        Pose2 t = ApproachBall.behind(self.position(), ball, directionDeg, 0, config.approach());
        return Decision.of(ApproachBall.toward(self, t, config.approach()), track.head(s));
    }

    private static boolean atFeet(Vector2 ball) {
        return ball.x() > 0 && ball.x() < AT_FEET_AHEAD && Math.abs(ball.y()) < AT_FEET_SIDE;
    }
}

package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.motion.walk.WalkConfig;

/**
 * Ours, On Ball's way to the ball when the robot knows where it is (AgentConfig.Approach): instead of
 * 4.6.2's Walk To Ball (turn, then walk straight at the ball) and the align orbit around it, walk with
 * the omnidirectional walk to the spot behind the ball on the line from the opponent goal's aim point
 * ({@link Facts#goalAim}: the centre from afar) through the ball, turning on the way, so the robot arrives facing the goal with the ball in front of
 * its right foot. A robot that is not yet behind the ball goes to a point beside it first, not through it.
 * The head is {@link Gaze}'s: the ball, or a pan for landmarks when the self belief goes stale.
 */
public final class ApproachBall implements Action {
    /** The omnidirectional walk's forward and sideways limits (m/s) that Move.Omni's shares are of (Body; all types). */
    private static final double FORWARD_LIMIT = WalkConfig.DEFAULT.maxForward(), LEFT_LIMIT = WalkConfig.DEFAULT.maxLeft();

    private final AgentConfig config;
    private final AgentConfig.Approach a;
    private final Gaze gaze;

    public ApproachBall(AgentConfig config) {
        this.config = config;
        this.a = config.approach();
        this.gaze = new Gaze(config);
    }

    /**
     * The robot knows where it is (a fresh, confident self belief), the ball and the field: the approach
     * steers by the self pose, and with a stale one a robot once walked 22 s round the ball and kicked it
     * toward its own goal (docs/matches.md, session 8).
     */
    public boolean usable(Situation s) { return Facts.selfLocalized(s, config) && target(s) != null; }

    /**
     * Where to go, own frame, and the heading to arrive with (toward the goal); null without a self pose,
     * a ball or a field.
     */
    Pose2 target(Situation s) {
        Pose2 self = Facts.self(s, config);
        Vector2 ball = Facts.ballGlobal(s, config);
        if (self == null || ball == null || s.field() == null) return null;
        Vector2 toGoal = Facts.goalAim(s, ball).minus(ball);
        if (!(toGoal.norm() > 1e-6)) return null;
        // The right foot's kick wants the torso beside the ball by the spot's side offset (spotY < 0: ball to the right).
        return behind(self.position(), ball, toGoal.angleDeg(), config.kick().spotY(), a);
    }

    /**
     * The pose to walk to for a ball to be played along {@code dirDeg} (field frame): a.behind() behind the ball and
     * {@code side} to its right (the ball that far left of the torso), facing dirDeg; for a robot not yet behind the ball,
     * the point beside it (a.sideClearance() out on the robot's side) first, not through the ball.
     */
    static Pose2 behind(Vector2 self, Vector2 ball, double dirDeg, double side, AgentConfig.Approach a) {
        Vector2 g = Vector2.polar(1, dirDeg);
        Vector2 left = new Vector2(-g.y(), g.x());
        Vector2 r = self.minus(ball);
        if (r.dot(g) > -0.6 * a.behind()) {
            double towards = r.dot(left) >= 0 ? 1 : -1;
            Vector2 way = ball.minus(g.times(a.behind())).plus(left.times(towards * a.sideClearance()));
            return new Pose2(way.x(), way.y(), dirDeg);
        }
        Vector2 spot = ball.minus(g.times(a.behind())).minus(left.times(side));
        return new Pose2(spot.x(), spot.y(), dirDeg);
    }

    @Override
    public Decision decide(Situation s) {
        Pose2 t = target(s);
        Pose2 self = Facts.self(s, config);
        if (t == null || self == null) return Decision.of(Move.STAND, gaze.head(s));
        // The head follows the ball while the self belief is fresh and pans for landmarks when it is not.
        return Decision.of(toward(self, t, a), gaze.head(s));
    }

    /**
     * The omnidirectional walk from {@code self} to the pose {@code t}: facing the way beyond faceWayBeyond, turning to
     * t's heading within it, full speed beyond slowWithin and proportionally slower within it (never below minShare).
     * Also the keeper's Challenge's last metre (it side-steps to its point rather than turning round for a few cm).
     */
    public static Move.Omni toward(Pose2 self, Pose2 t, AgentConfig.Approach a) {
        Vector2 d = t.position().minus(self.position()).rotate(-self.thetaDeg());   // body frame
        double dist = d.norm();
        double faceErr = dist > a.faceWayBeyond() ? d.angleDeg() : Angles.difference(t.thetaDeg(), self.thetaDeg());
        double turn = faceErr / a.turnFullDeg();
        double scale = Math.max(a.minShare(), Math.min(1, dist / a.slowWithin()));
        // Shares of the walk's limits that walk toward the spot: the sideways limit is a ninth of the forward one, so
        // equal shares of both (as before session 18) walked ~6 deg off the way, and the last 0.1 m sideways took
        // seconds at 3 cm/s. The larger share is the scale.
        double fx = d.x() / FORWARD_LIMIT, fy = d.y() / LEFT_LIMIT, big = Math.max(Math.abs(fx), Math.abs(fy));
        double fwd = big > 1e-12 ? fx / big * scale : 0, left = big > 1e-12 ? fy / big * scale : 0;
        // Badly turned, the robot turns first rather than walking sideways across the field.
        if (Math.abs(faceErr) > 60 && dist > a.faceWayBeyond()) { fwd *= 0.2; left *= 0.2; }
        return new Move.Omni(fwd, left, turn);
    }

    /** At the spot behind the ball (not the point beside it), facing the goal. */
    @Override
    public boolean done(Situation s) {
        Pose2 t = target(s);
        Pose2 self = Facts.self(s, config);
        if (t == null || self == null) return false;
        Vector2 ball = Facts.ballGlobal(s, config);
        boolean behind = self.position().minus(ball).dot(Vector2.polar(1, t.thetaDeg())) <= -0.6 * a.behind();
        return behind && t.position().distanceTo(self.position()) <= a.arriveDistance()
                && Math.abs(Angles.difference(t.thetaDeg(), self.thetaDeg())) <= a.arriveDeg();
    }
}

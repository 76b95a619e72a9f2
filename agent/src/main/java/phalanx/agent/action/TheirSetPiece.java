package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * Ours (issue 18): the field players keep out of what the referee clears at the opponents' kick-off and set pieces.
 * Every cycle of their kick-off, kick-in, free kick, corner or goal kick the server moves each of our robots whose box
 * meets a 2 m sphere round the ball 2.5 m away (SoccerRuleAspect::ClearPlayers, FreeKickDistance, FreeKickMoveDist),
 * at their kick-off also every robot in their half, at their goal kick every robot in their penalty area
 * (docs/protocol.md "Their set pieces"). The move sets a walking robot down mid-stride and it falls: in session 20's
 * g4 our player 10 walked toward the ball at their kick-off, was moved twice and fell twice before play began.
 * So during their set piece a walk's target is moved out of those places, and a player that would go to the ball
 * stands at the ball's distance on its line to our goal instead, facing the ball.
 */
public final class TheirSetPiece {
    /** Places are kept this far inside the field's lines. */
    private static final double FIELD_INSET = 0.3;
    private final AgentConfig config;
    private WalkToCoordinate keepOut;

    public TheirSetPiece(AgentConfig config) { this.config = config; }

    /** The opponents own the play mode (their kick-off or set piece; an offside of ours is theirs too). */
    public static boolean theirs(Situation s) {
        Side ours = s.belief() == null ? null : s.belief().side();
        PlayMode m = s.playMode();
        if (ours == null || m == null || m == PlayMode.GAME_OVER) return false;
        Side owner = m.owner();
        if (owner == null || m == PlayMode.GOAL_LEFT || m == PlayMode.GOAL_RIGHT) return false;
        Side kicker = m == PlayMode.OFFSIDE_LEFT || m == PlayMode.OFFSIDE_RIGHT ? owner.opposite() : owner;
        return kicker != ours;
    }

    /**
     * The action to run instead of {@code running} during their set piece: {@code running} itself when it is a walk to a
     * point that is allowed from a place that is allowed, else a walk to the nearest allowed point (for a walk to a
     * point), or to the point on the ball's line to our goal at the keep-out distance (for anything that goes to the ball).
     * Outside their set pieces, or without a ball or field, {@code running}.
     */
    public Action adjust(Situation s, Action running) {
        Vector2 ball = Facts.ballGlobal(s, config);
        Pose2 self = Facts.self(s, config);
        if (!config.setPieces().enabled() || !theirs(s) || ball == null || s.field() == null || self == null) { keepOut = null; return running; }
        Vector2 want;
        if (running instanceof WalkToCoordinate w) {
            want = w.target().position();
            if (allowed(s, ball, want) && allowed(s, ball, self.position())) { keepOut = null; return running; }
        } else if (running instanceof LookStraight || running instanceof LookForBall || running instanceof TurnToLocalize) {
            if (allowed(s, ball, self.position())) { keepOut = null; return running; }
            want = self.position();
        } else {
            want = wall(s.field(), ball);
        }
        Vector2 to = nearestAllowed(s, ball, want);
        double face = ball.minus(to).norm() < 1e-6 ? 0 : ball.minus(to).angleDeg();
        if (keepOut == null) keepOut = new WalkToCoordinate(config, to.x(), to.y(), face);
        else keepOut.target(to.x(), to.y(), face);
        return keepOut;
    }

    /** The point on the line from the ball to our goal's centre at the keep-out distance. */
    private Vector2 wall(FieldSpec f, Vector2 ball) {
        Vector2 toGoal = new Vector2(-f.halfLength(), 0).minus(ball);
        double n = toGoal.norm();
        Vector2 u = n < 1e-6 ? new Vector2(-1, 0) : toGoal.times(1 / n);
        return ball.plus(u.times(config.setPieces().keepOut()));
    }

    /** Outside the ball's keep-out circle, in our half at their kick-off and out of their penalty area at their goal kick. */
    boolean allowed(Situation s, Vector2 ball, Vector2 p) {
        AgentConfig.SetPieces k = config.setPieces();
        if (p.distanceTo(ball) < k.keepOut() - k.tolerance()) return false;
        if (kickOff(s.playMode()) && p.x() > -k.halfMargin()) return false;
        return !(goalKick(s.playMode()) && inTheirArea(s.field(), p, k.halfMargin()));
    }

    /** {@code p} moved out of the keep-out circle (radially), into our half, out of their area, as the mode asks. */
    Vector2 nearestAllowed(Situation s, Vector2 ball, Vector2 p) {
        AgentConfig.SetPieces k = config.setPieces();
        Vector2 q = p;
        if (kickOff(s.playMode())) q = new Vector2(Math.min(q.x(), -k.halfMargin() - k.tolerance()), q.y());
        if (goalKick(s.playMode()) && inTheirArea(s.field(), q, k.halfMargin()))
            q = new Vector2(s.field().halfLength() - s.field().penaltyDepth() - k.halfMargin() - k.tolerance(), q.y());
        Vector2 r = q.minus(ball);
        double n = r.norm();
        if (n < k.keepOut()) {
            Vector2 u = n < 1e-6 ? wall(s.field(), ball).minus(ball).times(1 / k.keepOut()) : r.times(1 / n);
            q = ball.plus(u.times(k.keepOut()));
            if (kickOff(s.playMode()) && q.x() > -k.halfMargin()) q = wall(s.field(), ball);
        }
        return s.field().clamp(q, FIELD_INSET);
    }

    private static boolean kickOff(PlayMode m) { return m == PlayMode.KICK_OFF_LEFT || m == PlayMode.KICK_OFF_RIGHT; }

    private static boolean goalKick(PlayMode m) { return m == PlayMode.GOAL_KICK_LEFT || m == PlayMode.GOAL_KICK_RIGHT; }

    private static boolean inTheirArea(FieldSpec f, Vector2 p, double margin) {
        return p.x() >= f.halfLength() - f.penaltyDepth() - margin && Math.abs(p.y()) <= f.penaltyWidth() / 2 + margin;
    }
}

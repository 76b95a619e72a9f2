package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * 4.6.1 Find Opponent's Goal: Scan until the goal's direction is known. The goal posts are
 * landmarks of the self-localization, so "the goal became visible" is read as "the self belief is
 * fresh and confident": the goal's direction then follows from the pose (and stays right after
 * the head has turned away).
 */
public final class FindOpponentGoal extends SearchAction {

    public FindOpponentGoal(AgentConfig config) { super(config, new Scan(config)); }

    @Override
    protected Move searching(Situation s) { return Move.STAND; }

    @Override
    protected Decision found(Situation s) {
        Vector2 rel = Facts.relative(s, config, s.field().opponentGoal());
        return Decision.of(Move.STAND, TrackObject.toward(rel, 0.4, s, config));
    }

    @Override
    public boolean done(Situation s) { return Facts.selfLocalized(s, config) && s.field() != null; }

    /**
     * The direction to aim at the opponent goal from a point of the own frame ({@link Facts#goalAim}), relative to the
     * body's heading (degrees, + left); NaN without a self pose.
     */
    public static double goalBearingFrom(Situation s, AgentConfig c, Vector2 from) {
        Pose2 self = Facts.self(s, c);
        if (self == null || from == null || s.field() == null) return Double.NaN;
        Vector2 d = Facts.goalAim(s, from).minus(from);
        return phalanx.model.field.Angles.difference(d.angleDeg(), self.thetaDeg());
    }
}

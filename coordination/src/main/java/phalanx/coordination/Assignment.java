package phalanx.coordination;

import phalanx.coordination.formation.Role;
import phalanx.coordination.subsets.Subset;
import phalanx.model.field.Vector2;

/**
 * One player's part of the team plan, in the team's own frame.
 *
 * @param id             uniform number
 * @param subset         its coordination subset
 * @param action         what to do
 * @param role           its formation role, or null (inactive players, Wait mode)
 * @param target         where to go, or null (LOCALIZE, WAIT, or a goalkeeper without a formation)
 * @param orientationDeg the heading to take at the target: towards the ball, or for the on-ball player
 *                       from the ball towards the opponent goal; NaN when there is no target
 */
public record Assignment(int id, Subset subset, Action action, Role role, Vector2 target, double orientationDeg) {
    public boolean onBall() { return action == Action.ON_BALL; }
}

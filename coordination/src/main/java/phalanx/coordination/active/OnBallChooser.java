package phalanx.coordination.active;

import java.util.List;
import phalanx.coordination.CoordinationConfig.OnBallConfig;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.model.field.Angles;
import phalanx.model.field.Vector2;

/**
 * The on-ball player (thesis 5.8): the active player minimising Value_i = d_i + a·θ_i, where d_i is its
 * distance to the ball and θ_i (degrees) how far it stands off the line from the ball to the opponent
 * goal — the angle between its approach (player → ball) and the shot (ball → goal), 0 when it is right
 * behind the ball. (The thesis's "sum of the absolute angles between the agent and the ball and between
 * the ball and the opponent's goal" read as the turn the player must make around the ball.) The previous
 * on-ball player's value is lowered by the hysteresis (1) so that near-ties do not flip every round.
 */
public final class OnBallChooser {
    private OnBallChooser() {}

    /** θ_i in degrees, 0..180. */
    public static double angleOff(Vector2 player, Vector2 ball, Vector2 goal) {
        Vector2 approach = ball.minus(player), shot = goal.minus(ball);
        if (approach.norm() == 0 || shot.norm() == 0) return 0;
        return Math.abs(Angles.difference(approach.angleDeg(), shot.angleDeg()));
    }

    public static double value(PlayerBelief p, Vector2 ball, Vector2 goal, OnBallConfig c, int previousOnBall) {
        double v = p.ballDistance() + c.angleWeight() * angleOff(p.position(), ball, goal);
        return p.id() == previousOnBall ? v - c.hysteresis() : v;
    }

    /** The uniform number of the on-ball player, or 0 when the list is empty. */
    public static int choose(List<PlayerBelief> active, Vector2 ball, Vector2 goal, OnBallConfig c,
                             int previousOnBall) {
        int best = 0;
        double bestValue = Double.POSITIVE_INFINITY;
        for (PlayerBelief p : active) {
            double v = value(p, ball, goal, c, previousOnBall);
            if (v < bestValue) { bestValue = v; best = p.id(); }
        }
        return best;
    }
}

package phalanx.coordination.active;

import java.util.List;
import phalanx.coordination.CoordinationConfig.ActiveWeights;
import phalanx.coordination.CoordinationConfig.CollisionConfig;
import phalanx.coordination.features.FieldUtility;
import phalanx.coordination.features.RouteCollision;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * Phase 4 of Algorithm 3, "Coordinate Active Players" (thesis 5.8, Algorithm 4): the on-ball player goes
 * to the ball; every ordered choice of distinct candidates for the other active players (72 for two
 * players and nine candidates) is scored and the cheapest kept. The cost sums over all active players,
 * the on-ball one included:
 * <pre>  w_d·C_d + w_c·C_c − w_u·C_u − w_t·C_t − w_h·C_h</pre>
 * C_d distance start→target; C_c potential collisions with the other routes ({@link RouteCollision});
 * C_u |field utility| of the target; C_t distances from the target to the other targets; C_h |Δx| from
 * the target to the other targets. Weights (1, 1, 1/7, 1, 1).
 */
public final class ActiveMapper {
    private ActiveMapper() {}

    /**
     * @param assignment candidate index per other player, in the order given
     * @param cost       the cost of the whole mapping
     * @param evaluated  how many mappings were scored (n!/(n−k)! for n candidates and k players)
     */
    public record ActiveMapping(int[] assignment, double cost, int evaluated) {}

    /**
     * @param onBall     the on-ball player's position (its target is the ball)
     * @param others     the other active players' positions (0, 1 or 2); at most as many as candidates
     * @param candidates the active positions
     */
    public static ActiveMapping map(Vector2 onBall, Vector2 ball, List<Vector2> others, List<Vector2> candidates,
                                    FieldSpec field, ActiveWeights w, CollisionConfig c) {
        int k = others.size(), n = candidates.size();
        if (k > 2) throw new IllegalArgumentException("Algorithm 4 maps at most two players besides the on-ball one, got " + k);
        if (k > n) throw new IllegalArgumentException(k + " players but only " + n + " candidate positions");
        Vector2[] starts = new Vector2[k + 1], targets = new Vector2[k + 1];
        starts[0] = onBall;
        targets[0] = ball;
        for (int i = 0; i < k; i++) starts[i + 1] = others.get(i);
        int[] best = new int[k];
        double bestCost = Double.POSITIVE_INFINITY;
        int evaluated = 0;
        if (k == 0) return new ActiveMapping(best, cost(starts, targets, field, w, c), 1);
        for (int i = 0; i < n; i++) {
            targets[1] = candidates.get(i);
            if (k == 1) {
                double cost = cost(starts, targets, field, w, c);
                evaluated++;
                if (cost < bestCost) { bestCost = cost; best[0] = i; }
                continue;
            }
            for (int j = 0; j < n; j++) {
                if (j == i) continue;
                targets[2] = candidates.get(j);
                double cost = cost(starts, targets, field, w, c);
                evaluated++;
                if (cost < bestCost) { bestCost = cost; best[0] = i; best[1] = j; }
            }
        }
        return new ActiveMapping(best, bestCost, evaluated);
    }

    /** ActiveCost of one mapping: player i goes from starts[i] to targets[i]. */
    public static double cost(Vector2[] starts, Vector2[] targets, FieldSpec field, ActiveWeights w,
                              CollisionConfig c) {
        int m = starts.length;
        double total = 0;
        for (int i = 0; i < m; i++) {
            Vector2 s = starts[i], t = targets[i];
            double cd = s.distanceTo(t), cc = 0, ct = 0, ch = 0;
            for (int j = 0; j < m; j++) {
                if (j == i) continue;
                cc += RouteCollision.cost(s.x(), s.y(), t.x(), t.y(),
                        starts[j].x(), starts[j].y(), targets[j].x(), targets[j].y(), c);
                ct += t.distanceTo(targets[j]);
                ch += Math.abs(t.x() - targets[j].x());
            }
            double cu = Math.abs(FieldUtility.of(t, field));
            total += w.distance() * cd + w.collision() * cc - w.utility() * cu - w.closeTargets() * ct
                    - w.stretch() * ch;
        }
        return total;
    }
}

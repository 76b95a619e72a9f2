package phalanx.coordination.support;

import java.util.List;
import phalanx.coordination.CoordinationConfig.CollisionConfig;
import phalanx.coordination.CoordinationConfig.SupportWeights;
import phalanx.coordination.features.RouteCollision;
import phalanx.model.field.Vector2;

/**
 * The support evaluation function (thesis 5.12): SupportCost = Σ_i w_d·C_d,i + w_c·C_c,i over the support
 * players, C_d the distance from the player to its position, C_c its potential collisions
 * ({@link RouteCollision}) with the other support routes and with the fixed routes of the optimal active
 * mapping. A crossing of two support routes therefore counts in both players' C_c, a crossing with an
 * active route once. Distances and collisions are tabulated once per instance.
 */
public final class SupportCost {
    private final int n;
    private final Vector2[] agents, positions;
    private final double wd, wc;
    /** w_d·distance + w_c·collisions with fixed routes, per (agent, position). */
    private final double[] single;
    private final double[] distance;
    /** Collision cost (unweighted) per (agent a at p, agent b at q), index ((a*n+p)*n+b)*n+q. */
    private final double[] pair;

    /**
     * @param agents       support players' positions
     * @param positions    support positions, as many as agents
     * @param fixedStarts  starts of the routes that are already decided (the active mapping)
     * @param fixedTargets their targets
     */
    public SupportCost(List<Vector2> agents, List<Vector2> positions, List<Vector2> fixedStarts,
                       List<Vector2> fixedTargets, SupportWeights w, CollisionConfig c) {
        if (agents.size() != positions.size())
            throw new IllegalArgumentException(agents.size() + " support players but " + positions.size() + " positions");
        if (agents.size() > 20) throw new IllegalArgumentException("at most 20 support players, got " + agents.size());
        if (fixedStarts.size() != fixedTargets.size()) throw new IllegalArgumentException("fixed routes need a start and a target each");
        n = agents.size();
        this.agents = agents.toArray(new Vector2[0]);
        this.positions = positions.toArray(new Vector2[0]);
        wd = w.distance();
        wc = w.collision();
        single = new double[n * n];
        distance = new double[n * n];
        for (int a = 0; a < n; a++) {
            Vector2 s = this.agents[a];
            for (int p = 0; p < n; p++) {
                Vector2 t = this.positions[p];
                double coll = 0;
                for (int f = 0; f < fixedStarts.size(); f++) {
                    Vector2 fs = fixedStarts.get(f), ft = fixedTargets.get(f);
                    coll += RouteCollision.cost(s.x(), s.y(), t.x(), t.y(), fs.x(), fs.y(), ft.x(), ft.y(), c);
                }
                distance[a * n + p] = s.distanceTo(t);
                single[a * n + p] = wd * distance[a * n + p] + wc * coll;
            }
        }
        pair = new double[n * n * n * n];
        if (wc != 0) {
            for (int a = 0; a < n; a++) for (int p = 0; p < n; p++) for (int b = a + 1; b < n; b++) for (int q = 0; q < n; q++) {
                if (q == p) continue;
                double v = RouteCollision.cost(this.agents[a].x(), this.agents[a].y(), this.positions[p].x(), this.positions[p].y(),
                        this.agents[b].x(), this.agents[b].y(), this.positions[q].x(), this.positions[q].y(), c);
                pair[((a * n + p) * n + b) * n + q] = v;
                pair[((b * n + q) * n + a) * n + p] = v;
            }
        }
    }

    public int size() { return n; }
    public Vector2 agent(int a) { return agents[a]; }
    public Vector2 position(int p) { return positions[p]; }
    public double distance(int a, int p) { return distance[a * n + p]; }
    /** The part of the cost that depends on agent a and position p alone. */
    public double single(int a, int p) { return single[a * n + p]; }
    /** The collision weight; 0 makes the cost separable. */
    public double collisionWeight() { return wc; }
    /** What putting a at p and b at q adds to the cost: the crossing counts for both players. */
    public double pairCost(int a, int p, int b, int q) { return 2 * wc * pair[((a * n + p) * n + b) * n + q]; }

    /** The cost of a complete mapping, positionOf[a] = the position of agent a. */
    public double total(int[] positionOf) {
        double t = 0;
        for (int a = 0; a < n; a++) {
            t += single(a, positionOf[a]);
            for (int b = a + 1; b < n; b++) t += pairCost(a, positionOf[a], b, positionOf[b]);
        }
        return t;
    }
}

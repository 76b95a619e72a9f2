package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Situation;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Angles;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;

/**
 * 4.6.2 Avoid Obstacles with Algorithm 2 (escape angle set). Obstacles are the players seen within
 * the memory time and the goal posts, within 2 m. When one of them lies on the straight way to the
 * target, each obstacle gives a left and a right escape angle (the tangents at the clearance
 * distance); an escape angle inside another obstacle's forbidden interval is dropped; of the rest,
 * the escape way point (the tangent point, closest to the obstacle along the escape direction)
 * with the least angle overhead (turn from the current heading) plus distance overhead (detour to
 * the target) becomes the temporary target. The same obstacles give the same way point every
 * cycle, so the route does not flicker.
 */
public final class AvoidObstacles {
    /** One escape direction: its angle (degrees, body frame, + left) and its way point. */
    public record Escape(double angleDeg, Vector2 waypoint) {}

    private final AgentConfig config;

    public AvoidObstacles(AgentConfig config) { this.config = config; }

    /** The temporary target on the way to a body-relative target: the target itself when its way is clear. */
    public Vector2 route(Situation s, Vector2 target) {
        return route(obstacles(s), target, config.obstacles());
    }

    /** Players seen within the memory time and the goal posts, body-relative, within range. */
    public List<Vector2> obstacles(Situation s) {
        List<Vector2> out = new ArrayList<>();
        WorldBelief b = s.belief();
        if (b == null) return out;
        Pose2 self = Facts.self(s, config);
        addPlayers(out, b.teammates(), b.time(), self);
        addPlayers(out, b.opponents(), b.time(), self);
        FieldSpec f = s.field();
        if (self != null && f != null) {
            for (int sx = -1; sx <= 1; sx += 2) {
                for (int sy = -1; sy <= 1; sy += 2) {
                    double x = sx * f.halfLength(), y = sy * f.goalWidth() / 2;
                    if (!surelyOutOfRange(self, x, y)) add(out, self.toRelative(new Vector2(x, y)));
                }
            }
        }
        return out;
    }

    private void addPlayers(List<Vector2> out, List<PlayerBelief> players, double now, Pose2 self) {
        if (players == null) return;
        for (int i = 0; i < players.size(); i++) {   // indexed: no iterator every cycle
            PlayerBelief p = players.get(i);
            if (p == null || !(now - p.time() <= config.beliefs().playerMemorySeconds())) continue;
            if (self != null && p.global() != null && surelyOutOfRange(self, p.global().x(), p.global().y())) continue;
            add(out, Facts.relative(p, self));
        }
    }

    /**
     * True when an own-frame point lies beyond the range, with room for rounding: turning it into the
     * body frame keeps its distance, so {@link #add} would drop it; this skips the transform (run for
     * every player seen, every cycle).
     */
    private boolean surelyOutOfRange(Pose2 self, double x, double y) {
        return Math.hypot(x - self.x(), y - self.y()) > config.obstacles().range() + 1e-6;
    }

    private void add(List<Vector2> out, Vector2 rel) {
        if (rel != null && rel.isFinite() && rel.norm() <= config.obstacles().range()) out.add(rel);
    }

    /** Algorithm 2 and the way point choice, on body-relative obstacles. */
    public static Vector2 route(List<Vector2> obstacles, Vector2 target, AgentConfig.Obstacles c) {
        if (target == null || !target.isFinite() || !blocked(obstacles, target, c.clearance())) return target;
        List<Vector2> near = new ArrayList<>();
        double reach = target.norm() + c.clearance();
        for (int i = 0; i < obstacles.size(); i++) if (obstacles.get(i).norm() <= reach) near.add(obstacles.get(i));
        Escape best = null;
        double bestCost = Double.POSITIVE_INFINITY;
        for (Escape e : escapeAngleSet(near, c.clearance())) {
            double cost = c.angleWeight() * Math.toRadians(Math.abs(e.angleDeg()))
                    + e.waypoint().norm() + target.distanceTo(e.waypoint()) - target.norm();
            if (cost < bestCost) { bestCost = cost; best = e; }
        }
        return best == null ? target : best.waypoint();
    }

    /** True when an obstacle closer than the target lies within the clearance of the straight way to it. */
    static boolean blocked(List<Vector2> obstacles, Vector2 target, double clearance) {
        double len = target.norm();
        if (len < 1e-9) return false;
        double dx = target.x() * (1 / len), dy = target.y() * (1 / len);   // the unit direction, as target.times(1 / len)
        for (int i = 0; i < obstacles.size(); i++) {   // runs every cycle: no iterator, no vectors
            Vector2 o = obstacles.get(i);
            double along = o.x() * dx + o.y() * dy;
            if (along <= 0 || along >= len + clearance) continue;
            if (Math.abs(dx * o.y() - dy * o.x()) < clearance) return true;
        }
        return false;
    }

    /** Algorithm 2: every obstacle's two escape angles, less those inside another obstacle's forbidden interval. */
    public static List<Escape> escapeAngleSet(List<Vector2> obstacles, double clearance) {
        int n = obstacles.size();
        double[] bearing = new double[n], half = new double[n], dist = new double[n];
        for (int i = 0; i < n; i++) {
            Vector2 o = obstacles.get(i);
            dist[i] = o.norm();
            bearing[i] = o.angleDeg();
            // Tangent from the body to the circle of the clearance around the obstacle; inside it, sideways.
            half[i] = dist[i] <= clearance ? 90 : Math.toDegrees(Math.asin(clearance / dist[i]));
        }
        List<Escape> set = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int side = 1; side >= -1; side -= 2) {
                double a = Angles.normalize(bearing[i] + side * half[i]);
                if (forbiddenByOther(a, i, bearing, half)) continue;
                double along = dist[i] * Math.cos(Math.toRadians(half[i]));
                set.add(new Escape(a, Vector2.polar(Math.max(along, clearance), a)));
            }
        }
        return set;
    }

    private static boolean forbiddenByOther(double a, int i, double[] bearing, double[] half) {
        for (int j = 0; j < bearing.length; j++) {
            if (j != i && Math.abs(Angles.difference(a, bearing[j])) < half[j]) return true;
        }
        return false;
    }
}

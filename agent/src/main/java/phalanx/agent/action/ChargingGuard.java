package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * Keeps a field player from being taken off for charging (AgentConfig.Charging has the server's rule): a walk toward an
 * opponent close ahead is slowed below the referee's charging speed, unless the rule would call him rather than us
 * (near the ball, we head for it and are the nearer) or we are on the ball (touching it makes us immune). It changes
 * only the speed of a walk the action chose, never its way, so every action keeps its own logic.
 */
public final class ChargingGuard {
    private final AgentConfig config;

    public ChargingGuard(AgentConfig config) { this.config = config; }

    public Decision apply(Situation s, Decision d) {
        Move m = limit(s, d.move());
        return m == d.move() ? d : new Decision(m, d.head(), d.beam());
    }

    /** The move, or the same move slower when it walks into an opponent the referee would call us for. */
    public Move limit(Situation s, Move m) {
        AgentConfig.Charging c = config.charging();
        if (!c.enabled()) return m;
        Vector2 way = way(m, c.speedShare());
        if (way == null) return m;
        WorldBelief b = s.belief();
        if (b == null || b.opponents() == null) return m;
        Vector2 ball = Facts.ball(s, config);
        if (ball != null && ball.norm() <= c.onBallWithin()) return m;
        Pose2 self = Facts.self(s, config);
        List<PlayerBelief> opponents = b.opponents();
        for (int i = 0; i < opponents.size(); i++) {
            PlayerBelief p = opponents.get(i);
            if (p == null || !(b.time() - p.time() <= config.beliefs().playerMemorySeconds())) continue;
            Vector2 rel = Facts.relative(p, self);
            if (rel == null || !rel.isFinite() || rel.norm() > c.range() || angleDeg(way, rel) > c.aheadDeg()) continue;
            if (ball != null && hisFoul(ball, rel, way, c)) continue;
            return slowed(m, c.speedShare());
        }
        return m;
    }

    /**
     * The move at most at the share of the walk's limits that keeps the torso under the referee's charging speed, whoever
     * is near: for a goalkeeper outside its area, which the rule no longer spares (Goalkeeper's Challenge).
     */
    public static Move belowChargingSpeed(Move m, AgentConfig.Charging c) {
        return way(m, c.speedShare()) == null ? m : slowed(m, c.speedShare());
    }

    /** Near the ball, heading for it more than at him and nearer to it than he is: the rule calls him, not us. */
    private static boolean hisFoul(Vector2 ball, Vector2 him, Vector2 way, AgentConfig.Charging c) {
        double ours = ball.norm(), his = ball.distanceTo(him);
        return Math.min(ours, his) <= c.ballRulesDistance() && ours + c.nearerMargin() < his
                && angleDeg(way, ball) < angleDeg(way, him);
    }

    /**
     * The body-frame direction of a move that walks faster than the share, or null: the slow walk is under the speed
     * already, and sideways (0.1 m/s) and backward (0.4 m/s) limits are at or under it, so only forward walking counts.
     */
    private static Vector2 way(Move m, double share) {
        if (m instanceof Move.Walk w) return w.slow() ? null : new Vector2(1, 0);
        if (m instanceof Move.Omni o && o.forward() > share) return new Vector2(1, 0);
        return null;
    }

    private static Move slowed(Move m, double share) {
        if (m instanceof Move.Walk w) return new Move.Walk(w.lean(), true);
        Move.Omni o = (Move.Omni) m;
        return new Move.Omni(share, o.left(), o.turn());
    }

    private static double angleDeg(Vector2 a, Vector2 b) {
        double n = a.norm() * b.norm();
        if (n < 1e-12) return 0;
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (a.x() * b.x() + a.y() * b.y()) / n))));
    }
}

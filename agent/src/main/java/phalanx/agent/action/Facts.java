package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Situation;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.fall.FallState;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * The belief questions every action asks, answered safely: a missing belief, a NaN or a ball never
 * seen give "not known" (null or false), never an exception. Actions read the belief only through here.
 */
public final class Facts {
    private Facts() {}

    /** The ball relative to the body when seen within the lost time and finite, else null. */
    public static Vector2 ball(Situation s, AgentConfig c) {
        WorldBelief b = s.belief();
        if (b == null || b.ballRelative() == null || !b.ballRelative().isFinite()) return null;
        return b.ballAge() <= c.beliefs().ballLostSeconds() ? b.ballRelative() : null;
    }

    /** The ball relative to the body when seen just now (in view; a ball heard from teammates is not), else null. */
    public static Vector2 ballInView(Situation s, AgentConfig c) {
        WorldBelief b = s.belief();
        if (b == null || b.ballHeard() || b.ballRelative() == null || !b.ballRelative().isFinite()) return null;
        return b.ballAge() <= c.beliefs().ballFreshSeconds() ? b.ballRelative() : null;
    }

    /** True when the ball belief is the teammates' report, not own sight (WorldBelief.ballHeard). */
    public static boolean ballHeard(Situation s) {
        WorldBelief b = s.belief();
        return b != null && b.ballHeard();
    }

    /** The ball in the own frame when known and finite, else null. */
    public static Vector2 ballGlobal(Situation s, AgentConfig c) {
        WorldBelief b = s.belief();
        if (b == null || b.ballGlobal() == null || !b.ballGlobal().isFinite()) return null;
        return b.ballAge() <= c.beliefs().ballLostSeconds() ? b.ballGlobal() : null;
    }

    /** The ball's velocity in the own frame, or null (not tracked, NaN). */
    public static Vector2 ballVelocity(Situation s) {
        WorldBelief b = s.belief();
        if (b == null || b.ballVelocity() == null || !b.ballVelocity().isFinite()) return null;
        return b.ballVelocity();
    }

    /** The self pose when it exists, is finite and was refreshed within the usable age, else null. */
    public static Pose2 self(Situation s, AgentConfig c) {
        WorldBelief b = s.belief();
        if (b == null || !finite(b.self())) return null;
        return b.selfAge() <= c.beliefs().selfUsableSeconds() ? b.self() : null;
    }

    /** True when the self belief is fresh and confident (Turn To Localize's goal). */
    public static boolean selfLocalized(Situation s, AgentConfig c) {
        WorldBelief b = s.belief();
        return b != null && finite(b.self()) && b.selfAge() <= c.beliefs().selfFreshSeconds()
                && b.selfConfidence() >= c.beliefs().selfConfidence();
    }

    /** True when an opponent seen within the player memory time is believed within {@code radius} of a field point. */
    public static boolean opponentNear(Situation s, AgentConfig c, Vector2 point, double radius) {
        WorldBelief b = s.belief();
        return b != null && point != null && anyoneNear(b.opponents(), b.time(), point, radius, c);
    }

    /** True when one of these players, seen within the player memory time, is believed within {@code radius} of a point. */
    public static boolean anyoneNear(List<PlayerBelief> players, double now, Vector2 point,
                                     double radius, AgentConfig c) {
        if (players == null || point == null) return false;
        for (PlayerBelief p : players) {
            if (seen(p, now, c) && p.global().distanceTo(point) <= radius) return true;
        }
        return false;
    }

    /** A player with a field position, seen within the player memory time. */
    public static boolean seen(PlayerBelief p, double now, AgentConfig c) {
        return p != null && p.global() != null && now - p.time() <= c.beliefs().playerMemorySeconds();
    }

    /**
     * A player's position relative to the body now: from his own-frame position and our pose when both are known (a
     * remembered player's relative vector goes stale as we walk; his own-frame position does not), else as last seen.
     */
    public static Vector2 relative(PlayerBelief p, Pose2 self) {
        return self != null && p.global() != null ? self.toRelative(p.global()) : p.relative();
    }

    /** The fall state, STANDING when unknown. */
    public static FallState fall(Situation s) {
        WorldBelief b = s.belief();
        return b == null || b.fall() == null ? FallState.STANDING : b.fall();
    }

    /** The bearing of a body-relative point, degrees (+ left). */
    public static double bearing(Vector2 relative) { return relative.angleDeg(); }

    /** A point of the own frame relative to the body, or null without a self pose. */
    public static Vector2 relative(Situation s, AgentConfig c, Vector2 global) {
        Pose2 self = self(s, c);
        return self == null || global == null ? null : self.toRelative(global);
    }

    /**
     * Where a kick or a dribble from {@code from} aims at the opponent goal (FieldSpec.opponentGoalAim), the
     * posts brought in by AIM_POST_MARGIN. Null without a field.
     */
    public static Vector2 goalAim(Situation s, Vector2 from) {
        return s.field() == null ? null : s.field().opponentGoalAim(from, AIM_POST_MARGIN);
    }

    /**
     * Half the angle between the goal's posts (brought in by AIM_POST_MARGIN) as seen from {@code from}, degrees: a
     * ball sent from there within this of the aim goes in. 0 without a field or from on or behind the goal line.
     */
    public static double goalMouthHalfAngle(Situation s, Vector2 from) {
        return s.field() == null ? 0 : s.field().opponentGoalHalfAngle(from, AIM_POST_MARGIN);
    }

    /** The posts stand outside the 2.1 m mouth (naov4/goal.rsg): the ball's radius, 0.042 m, and 0.1 m to spare. */
    static final double AIM_POST_MARGIN = 0.15;

    static boolean finite(Pose2 p) {
        return p != null && Double.isFinite(p.x()) && Double.isFinite(p.y()) && Double.isFinite(p.thetaDeg());
    }

    /** v clamped to [lo, hi]; NaN gives lo. */
    static double clamp(double v, double lo, double hi) {
        if (!(v >= lo)) return lo;
        return Math.min(v, hi);
    }
}

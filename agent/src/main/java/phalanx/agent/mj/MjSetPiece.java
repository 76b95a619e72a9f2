package phalanx.agent.mj;

import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;

/**
 * Where rcssservermj's referee lets our players stand in a set piece (soccer_referee.py
 * {@code _penalize_misplaced_players}, read in rcsssmj 0.2.1): each referee step it drops any player standing where it
 * must not beyond the touch line ({@code _penalize}). In our own frame, with R the centre circle's radius (5.5 m):
 * <ul>
 * <li>their free kick, direct free kick, kick-in or corner: nobody of ours within R of the ball;</li>
 * <li>their kick-off: nobody of ours in their half or within R of the centre spot;</li>
 * <li>their goal kick: nobody of ours in their goalie area;</li>
 * <li>our kick-off: nobody in their half but the player nearest the centre (the taker, inside the circle).</li>
 * </ul>
 * A place to walk to is moved out of what is forbidden (by {@code margin}, our choice: see {@link Config}), and a walk whose
 * straight line would cross the forbidden circle goes round it. The same geometry, with a circle of its own round the
 * ball and nothing else, keeps a player off the ball ({@link #around}): the double-touch rule's barred player.
 * Everything in the team's own frame (+x towards the opponent goal).
 */
record MjSetPiece(Vector2 centre, double radius, double maxX, double boxMinX, double boxHalfY, double margin) {
    /**
     * Ours. {@code margin}: targets lie this far beyond the forbidden circle or line: MjBehaviour stops within arriveM
     * (0.4 m) of a target, the T1 sways and steps on a little after stopping, the ball as we believe it is off by up to
     * 0.06 m (docs/rcssservermj.md, vision); 1.0 m leaves 0.3 m besides (measured on the server: MjSetPieceTest and
     * docs/rcssservermj.md). {@code detour}, {@code detourDeg}: going round the circle, the waypoint lies detourDeg further
     * round, so far out that a walker steering at it circles this much beyond the target distance.
     */
    record Config(double margin, double detour, double detourDeg) {
        static final Config DEFAULT = new Config(1.0, 0.3, 30);
    }

    /** No restriction. */
    static final MjSetPiece NONE = new MjSetPiece(null, 0, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, 0, 0);

    /**
     * The restriction on our players in play mode {@code mode} (its wire name), {@code ourSide} +1 left, -1 right;
     * {@code taker}: this player is the one going to the ball (our kick-off lets it into their half).
     */
    static MjSetPiece of(String mode, int ourSide, MjField field, Vector2 ball, boolean taker, Config c) {
        if (mode == null || ourSide == 0) return NONE;
        String m = mode.toLowerCase(java.util.Locale.ROOT);
        boolean left = m.endsWith("_left"), right = m.endsWith("_right");
        if (!left && !right) return NONE;
        boolean theirs = ourSide > 0 ? right : left;
        double r = field.centreRadius();
        if (m.startsWith("kickoff_")) {
            if (theirs) return new MjSetPiece(Vector2.ZERO, r, -c.margin(), Double.POSITIVE_INFINITY, 0, c.margin());
            return taker ? NONE : new MjSetPiece(null, 0, -c.margin(), Double.POSITIVE_INFINITY, 0, c.margin());
        }
        if (!theirs) return NONE;
        if (m.startsWith("goal_kick_"))
            return new MjSetPiece(null, 0, Double.POSITIVE_INFINITY, field.halfLength() - field.goalieArea()[0], field.goalieArea()[1] / 2, c.margin());
        boolean freeKick = m.startsWith("free_kick_") || m.startsWith("direct_free_kick_") || m.startsWith("kickin_")
                || m.startsWith("corner_kick_");
        if (!freeKick || ball == null) return NONE;   // offside, penalties: the referee places nobody in them
        return new MjSetPiece(ball, r, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, 0, c.margin());
    }

    /** Only a circle of {@code radius} round {@code ball} to keep out of (targets {@code margin} beyond it). */
    static MjSetPiece around(Vector2 ball, double radius, double margin) {
        return new MjSetPiece(ball, radius, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, 0, margin);
    }

    /**
     * {@code p} moved out of our own goalie area grown by {@code margin}, to its nearest edge. The referee's illegal
     * defence (soccer_referee.py {@code _check_illegal_defense}, any play mode): more than two of a team in its own goalie
     * area for 5 steps, and the last to enter is dropped beyond the touch line. With the keeper there, a second player is
     * one too many only when a third comes: so field players' places stay out and only the one going to the ball enters.
     * Seen in MjKeeperServerTest before this: the keeper came out, walked back in last, and was dropped.
     */
    static Vector2 outOfOurGoalieArea(Vector2 p, MjField field, double margin) {
        double edgeX = -field.halfLength() + field.goalieArea()[0] + margin, edgeY = field.goalieArea()[1] / 2 + margin;
        if (p.x() >= edgeX || Math.abs(p.y()) >= edgeY) return p;
        return edgeX - p.x() <= edgeY - Math.abs(p.y()) ? new Vector2(edgeX, p.y()) : new Vector2(p.x(), Math.copySign(edgeY, p.y() == 0 ? 1 : p.y()));
    }

    /** Whether this restricts anything. */
    boolean restricts() {
        return centre != null || maxX < Double.POSITIVE_INFINITY || boxMinX < Double.POSITIVE_INFINITY;
    }

    /** The referee's own test: {@code p} stands where the referee drops a player (no margin). */
    boolean forbidden(Vector2 p) {
        return centre != null && p.distanceTo(centre) < radius || p.x() > maxX + margin
                || p.x() >= boxMinX && Math.abs(p.y()) <= boxHalfY;
    }

    /** {@code want} moved to the nearest place at least {@code margin} clear of everything forbidden. */
    Vector2 allowed(Vector2 want) {
        Vector2 q = want;
        if (q.x() > maxX) q = new Vector2(maxX, q.y());
        if (q.x() > boxMinX - margin && Math.abs(q.y()) < boxHalfY + margin) q = new Vector2(boxMinX - margin, q.y());
        if (centre != null) {
            double keep = radius + margin;
            Vector2 r = q.minus(centre);
            double n = r.norm();
            if (n < keep) {
                // straight out from the centre; from the centre itself towards our goal
                Vector2 u = n < 1e-6 ? new Vector2(-1, 0) : r.times(1 / n);
                q = centre.plus(u.times(keep));
                // our kick-off half: out of the circle on the line (both hold at their kick-off, whose circle is centred on x = 0)
                if (q.x() > maxX) q = new Vector2(maxX, Math.copySign(Math.sqrt(Math.max(0, keep * keep - maxX * maxX)), q.y() == 0 ? 1 : q.y()));
            }
        }
        return q;
    }

    /** Places are kept this far inside the field's lines (ours, as TheirSetPiece's on SimSpark), m. */
    static final double FIELD_INSET = 0.3;

    /**
     * As {@link #allowed(Vector2)}, and FIELD_INSET inside the field's lines: a place beyond one slides along the line to
     * where it leaves the grown circle (a free kick near our goal line pushes the keeper's spot behind the line).
     */
    Vector2 allowed(Vector2 want, MjField field) {
        Vector2 q = allowed(want);
        double hx = field.halfLength() - FIELD_INSET, hy = field.halfWidth() - FIELD_INSET;
        if (Math.abs(q.x()) > hx) q = slide(new Vector2(Math.copySign(hx, q.x()), q.y()), true);
        if (Math.abs(q.y()) > hy) q = slide(new Vector2(q.x(), Math.copySign(hy, q.y())), false);
        return q;
    }

    /** {@code p}, on a line x = p.x (alongX) or y = p.y, moved along it out of the grown circle, on its side of the centre. */
    private Vector2 slide(Vector2 p, boolean alongX) {
        if (centre == null) return p;
        double keep = radius + margin;
        double across = alongX ? p.x() - centre.x() : p.y() - centre.y();
        if (Math.abs(across) >= keep) return p;
        double half = Math.sqrt(keep * keep - across * across);
        double along = alongX ? p.y() - centre.y() : p.x() - centre.x();
        if (Math.abs(along) >= half) return p;
        double to = Math.copySign(half, along == 0 ? 1 : along);
        return alongX ? new Vector2(p.x(), centre.y() + to) : new Vector2(centre.x() + to, p.y());
    }

    /**
     * Where to walk now on the way from {@code self} to {@code target} (already {@link #allowed}): the target itself when
     * the straight line keeps out of the circle (grown by half the margin), else a waypoint round the circle on the
     * target's side, {@code detourDeg} further round from our own bearing from the centre (at most as far round as the
     * target).
     */
    Vector2 via(Vector2 self, Vector2 target, Config c) {
        if (centre == null || clear(self, target, radius + margin / 2)) return target;
        Vector2 from = self.minus(centre), to = target.minus(centre);
        double turn = Math.signum(from.cross(to));
        if (turn == 0) turn = 1;
        double step = Math.min(c.detourDeg(), Math.toDegrees(Math.acos(Math.max(-1, Math.min(1,
                from.dot(to) / Math.max(1e-9, from.norm() * to.norm()))))));
        Vector2 u = from.norm() < 1e-6 ? new Vector2(-1, 0) : from.times(1 / from.norm());
        // at (keep + detour) / cos(step), detourDeg ahead: a walker steering at it circles at keep + detour
        Vector2 w = centre.plus(u.rotate(turn * step).times((radius + margin + c.detour()) / Math.cos(Math.toRadians(step))));
        return w.x() > maxX ? new Vector2(maxX, w.y()) : w;
    }

    /** The segment a-b stays at least {@code keep} from the centre. */
    private boolean clear(Vector2 a, Vector2 b, double keep) {
        Vector2 ab = b.minus(a);
        double len2 = ab.dot(ab);
        double t = len2 < 1e-12 ? 0 : Math.max(0, Math.min(1, centre.minus(a).dot(ab) / len2));
        return a.plus(ab.times(t)).distanceTo(centre) >= keep;
    }

    /** The point on the line from the ball to our goal's centre at the circle's target distance: a wall instead of the ball. */
    Vector2 wall(Vector2 ball, MjField field) {
        Vector2 toGoal = new Vector2(-field.halfLength(), 0).minus(ball);
        double n = toGoal.norm();
        Vector2 u = n < 1e-6 ? new Vector2(-1, 0) : toGoal.times(1 / n);
        return allowed(ball.plus(u.times(radius + margin)), field);
    }
}

package phalanx.model.field;

import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;

/**
 * The field of one server version (thesis 3.1; DESIGN.md): 0.6.5 had 9 players on 21 x 14 m,
 * 0.6.6 and later have 11 players on 30 x 20 m. Lengths in metres, the origin at the centre spot,
 * +x towards the right-hand goal in the field frame.
 */
public record FieldSpec(String name, double length, double width, double goalWidth, double goalHeight,
                        double penaltyDepth, double penaltyWidth, double centreRadius, int players) {

    /** rcssserver3d 0.6.6 and later: the default. */
    public static final FieldSpec V066 = new FieldSpec("0.6.6+", 30, 20, 2.1, 0.8, 1.8, 3.9, 2.0, 11);
    /** rcssserver3d 0.6.5, the thesis's server. */
    public static final FieldSpec V065 = new FieldSpec("0.6.5", 21, 14, 2.1, 0.8, 1.8, 3.9, 1.8, 9);

    public static FieldSpec forPlayers(int players) {
        if (players == 11) return V066;
        if (players == 9) return V065;
        throw new IllegalArgumentException("players must be 9 or 11, got " + players);
    }

    public double halfLength() { return length / 2; }
    public double halfWidth() { return width / 2; }

    /**
     * A landmark in the field frame. Names are absolute for both teams: F1L is always at
     * (-L/2, W/2, 0), G1L at (-L/2, goalWidth/2, goalHeight) (recordings README, S6).
     */
    public Vector3 landmark(Landmark l) {
        double x = l.name().charAt(2) == 'L' ? -halfLength() : halfLength();
        boolean one = l.name().charAt(1) == '1';
        if (l.isGoalPost()) return new Vector3(x, one ? goalWidth / 2 : -goalWidth / 2, goalHeight);
        return new Vector3(x, one ? halfWidth() : -halfWidth(), 0);
    }

    /** A landmark in a team's own frame: the field frame for the left team, turned by 180° for the right. */
    public Vector3 landmark(Landmark l, Side side) {
        Vector3 p = landmark(l);
        return side == Side.RIGHT ? new Vector3(-p.x(), -p.y(), p.z()) : p;
    }

    /** True when the point lies on the field, with an optional margin outside the lines. */
    public boolean contains(Vector2 p, double margin) { return contains(p.x(), p.y(), margin); }

    /** {@link #contains(Vector2, double)} for a point given by its coordinates. */
    public boolean contains(double x, double y, double margin) {
        return Math.abs(x) <= halfLength() + margin && Math.abs(y) <= halfWidth() + margin;
    }

    /** The point moved inside the field, {@code inset} metres from the lines. */
    public Vector2 clamp(Vector2 p, double inset) {
        double hx = halfLength() - inset, hy = halfWidth() - inset;
        return new Vector2(Math.max(-hx, Math.min(hx, p.x())), Math.max(-hy, Math.min(hy, p.y())));
    }

    /** Centre of the opponent's goal line in the own frame. */
    public Vector2 opponentGoal() { return new Vector2(halfLength(), 0); }

    /**
     * Where to aim at the opponent goal from a point of the own frame: the point of its goal line where the
     * bisector of the angle between the two posts (each brought in by postMargin) meets it. Far out it is the
     * centre; from a sharp angle it moves toward the near post, so the window on either side of the aim is the
     * same angle (aiming at the centre from the goal line beside a post, the far post is the aim's edge).
     * The centre from on or behind the goal line.
     */
    public Vector2 opponentGoalAim(Vector2 from, double postMargin) {
        double post = goalWidth / 2 - postMargin;
        Vector2 centre = opponentGoal();
        if (from == null || !(from.x() < halfLength() - 1e-6) || post <= 0) return centre;
        Vector2 a = new Vector2(halfLength(), post).minus(from), b = new Vector2(halfLength(), -post).minus(from);
        Vector2 bisector = a.times(1 / a.norm()).plus(b.times(1 / b.norm()));
        double t = (halfLength() - from.x()) / bisector.x();
        return new Vector2(halfLength(), from.y() + bisector.y() * t);
    }

    /**
     * Half the angle between the opponent goal's posts (each brought in by postMargin) as seen from a point of the own
     * frame, degrees: a ball sent from there within this of {@link #opponentGoalAim} goes in. 0 from on or behind the line.
     */
    public double opponentGoalHalfAngle(Vector2 from, double postMargin) {
        double post = goalWidth / 2 - postMargin;
        if (from == null || !(from.x() < halfLength()) || post <= 0) return 0;
        double a = new Vector2(halfLength(), post).minus(from).angleDeg(), b = new Vector2(halfLength(), -post).minus(from).angleDeg();
        return Math.abs(Angles.difference(a, b)) / 2;
    }

    /** Centre of the own goal line in the own frame. */
    public Vector2 ownGoal() { return new Vector2(-halfLength(), 0); }
}

package phalanx.model.field;

/**
 * A position and orientation on the ground plane: metres and degrees, counter-clockwise from +x,
 * in the team's own frame (own goal at -x; for a right-side team that is the field turned by 180°).
 */
public record Pose2(double x, double y, double thetaDeg) {

    public Vector2 position() { return new Vector2(x, y); }

    /** A body-relative vector (+x forward, +y left) in this pose's frame. */
    public Vector2 toGlobal(Vector2 relative) {
        // position().plus(relative.rotate(thetaDeg)), the same arithmetic in one allocation (a hot path)
        double r = Math.toRadians(thetaDeg), c = Math.cos(r), s = Math.sin(r);
        return new Vector2(x + (c * relative.x() - s * relative.y()), y + (s * relative.x() + c * relative.y()));
    }

    /** A vector in this pose's frame, relative to the body (+x forward, +y left). */
    public Vector2 toRelative(Vector2 global) {
        // global.minus(position()).rotate(-thetaDeg), the same arithmetic in one allocation
        double dx = global.x() - x, dy = global.y() - y;
        double r = Math.toRadians(-thetaDeg), c = Math.cos(r), s = Math.sin(r);
        return new Vector2(c * dx - s * dy, s * dx + c * dy);
    }
}

package phalanx.localization.field;

/**
 * A position and orientation on the ground plane: metres and degrees, counter-clockwise from +x,
 * in the team's own frame (own goal at -x; for a right-side team that is the field turned by 180°).
 */
public record Pose2(double x, double y, double thetaDeg) {

    public Vector2 position() { return new Vector2(x, y); }

    /** A body-relative vector (+x forward, +y left) in this pose's frame. */
    public Vector2 toGlobal(Vector2 relative) {
        return position().plus(relative.rotate(thetaDeg));
    }

    /** A vector in this pose's frame, relative to the body (+x forward, +y left). */
    public Vector2 toRelative(Vector2 global) {
        return global.minus(position()).rotate(-thetaDeg);
    }
}

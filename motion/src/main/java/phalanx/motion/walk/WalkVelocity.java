package phalanx.motion.walk;

/**
 * A walk request or the walk's current velocity, in the robot's own frame.
 *
 * @param forward m/s, positive forward
 * @param left    m/s, positive to the robot's left
 * @param turnDeg deg/s, counter-clockwise (to the left) positive
 */
public record WalkVelocity(double forward, double left, double turnDeg) {
    public static final WalkVelocity ZERO = new WalkVelocity(0, 0, 0);

    public WalkVelocity {
        if (!Double.isFinite(forward) || !Double.isFinite(left) || !Double.isFinite(turnDeg))
            throw new IllegalArgumentException("walk velocity must be finite, got (" + forward + ", " + left + ", " + turnDeg + ")");
    }

    public boolean isZero() { return forward == 0 && left == 0 && turnDeg == 0; }
}

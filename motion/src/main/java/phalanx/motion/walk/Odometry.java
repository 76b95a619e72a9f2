package phalanx.motion.walk;

/**
 * How far the walk moved the robot in one cycle, as commanded (the velocity after limits, times the
 * cycle, times the measured scale of {@link WalkConfig}), in the robot's frame at the start of the
 * cycle: the arguments of the localization's {@code BeliefStore.odometry(forward, left, turnDeg)}.
 *
 * @param forward metres forward
 * @param left    metres to the left
 * @param turnDeg degrees counter-clockwise
 */
public record Odometry(double forward, double left, double turnDeg) {
    public static final Odometry NONE = new Odometry(0, 0, 0);
}

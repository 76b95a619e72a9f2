package phalanx.motion.control;

/**
 * The head's two hinges (HJ1 yaw, HJ2 pitch) follow a target angle by a P-controller; motion files and
 * the walk leave the head alone, so the agent's head actions steer it through this.
 */
public final class HeadServo {
    /** Gain, 1/s: 8/s x 20 ms closes 16 % of the error a cycle, stable with one cycle of latency. */
    public static final double GAIN = 8.0;
    /** The velocity sent at most, rad/s (the server caps every hinge at about 6.14). */
    public static final double MAX_RAD_PER_S = 6.0;

    private HeadServo() {}

    /** The hinge velocity in rad/s that moves a head joint from {@code currentDeg} toward {@code targetDeg}. */
    public static double velocity(double targetDeg, double currentDeg) {
        double v = GAIN * Math.toRadians(targetDeg - currentDeg);
        return Math.max(-MAX_RAD_PER_S, Math.min(MAX_RAD_PER_S, v));
    }
}

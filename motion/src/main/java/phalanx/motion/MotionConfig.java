package phalanx.motion;

/**
 * The motion module's constants, each defaulting to the thesis value (section in the comment) or,
 * where the thesis is silent or the real server differs, to the measured server fact.
 *
 * @param cycleSeconds        simulation cycle: 0.02 s (DESIGN.md, recordings README)
 * @param maxJointSpeed       the hinge speed cap in rad/s: 351.77 deg/s = 6.1395 rad/s (naoleg.rsg,
 *                            DESIGN.md "capped at about 6.14 rad/s"); commands beyond it are clamped
 * @param latencyCycles       cycles before a command shows in the joint readings: 1 on the real
 *                            server (recordings README, "Timing rules"); 0 gives the thesis's formula
 *                            that trusts the reading as if it were current (4.5.2)
 * @param textPoseCycles      4.5.4 Duration: cycles per pose of a text motion, default 2
 * @param textPoseStep        4.5.4 PoseStep: poses advanced per step, default 1
 * @param walkSlowdownFactor  4.5.5 Walk Slowdown: phase durations scaled by "about 35 %"
 * @param turnGainMin         4.5.5 Turn Gain: lower end of the useful range, 0.3
 * @param turnGainMax         4.5.5 Turn Gain: upper end and default, 1.0
 * @param walkLeanDeg         4.5.5 Walk Leaning: how much a full lean (1.0) shortens the leaning
 *                            leg's step, in degrees of hip pitch; the thesis gives no number, 8 deg
 *                            is our choice (a third of a forward step's hip swing)
 * @param standBeforeSeconds  ours, not in the thesis: before a kick (any keyframe motion but a get-up or dive) the
 *                            walk, once stopped, stands this long in its crouch so the body is still when it starts;
 *                            0 kicks at once. 0.5 s: on the approach bench 16 of 30 first touches went over 8 m,
 *                            against 9 of 30 kicking at once (docs/matches.md, session 19)
 * @param standAfterSeconds   ours: after a keyframe motion the walk stands this long before it steps, easing the
 *                            joints from where the motion left them into its own crouch (WalkController.startFrom);
 *                            0 snaps them there and steps at once. 0.4 s: on the approach bench 3 falls in 30 trials
 *                            against 7 with 0 (docs/matches.md, session 20)
 */
public record MotionConfig(double cycleSeconds, double maxJointSpeed, int latencyCycles,
                           int textPoseCycles, int textPoseStep, double walkSlowdownFactor,
                           double turnGainMin, double turnGainMax, double walkLeanDeg, double standBeforeSeconds, double standAfterSeconds) {

    public static final MotionConfig DEFAULT = new MotionConfig(0.02, 6.1395, 1, 2, 1, 1.35, 0.3, 1.0, 8.0, 0.5, 0.4);

    public MotionConfig {
        positive(cycleSeconds, "cycleSeconds");
        positive(maxJointSpeed, "maxJointSpeed");
        if (latencyCycles < 0 || latencyCycles > 1) throw new IllegalArgumentException("latencyCycles must be 0 or 1, got " + latencyCycles);
        if (textPoseCycles < 1) throw new IllegalArgumentException("textPoseCycles (4.5.4 Duration) must be >= 1, got " + textPoseCycles);
        if (textPoseStep < 1) throw new IllegalArgumentException("textPoseStep (4.5.4 PoseStep) must be >= 1, got " + textPoseStep);
        if (!(walkSlowdownFactor >= 1.0)) throw new IllegalArgumentException("walkSlowdownFactor must be >= 1, got " + walkSlowdownFactor);
        positive(turnGainMin, "turnGainMin");
        if (!(turnGainMax >= turnGainMin)) throw new IllegalArgumentException("turnGainMax must be >= turnGainMin, got " + turnGainMax);
        if (!(walkLeanDeg >= 0) || !Double.isFinite(walkLeanDeg)) throw new IllegalArgumentException("walkLeanDeg must be >= 0, got " + walkLeanDeg);
        if (!(standBeforeSeconds >= 0 && standBeforeSeconds <= 5)) throw new IllegalArgumentException("standBeforeSeconds must be 0-5, got " + standBeforeSeconds);
        if (!(standAfterSeconds >= 0 && standAfterSeconds <= 5)) throw new IllegalArgumentException("standAfterSeconds must be 0-5, got " + standAfterSeconds);
    }

    public MotionConfig withLatencyCycles(int n) {
        return new MotionConfig(cycleSeconds, maxJointSpeed, n, textPoseCycles, textPoseStep, walkSlowdownFactor, turnGainMin, turnGainMax, walkLeanDeg, standBeforeSeconds, standAfterSeconds);
    }

    public MotionConfig withTextPose(int cycles, int step) {
        return new MotionConfig(cycleSeconds, maxJointSpeed, latencyCycles, cycles, step, walkSlowdownFactor, turnGainMin, turnGainMax, walkLeanDeg, standBeforeSeconds, standAfterSeconds);
    }

    public MotionConfig withStand(double beforeSeconds, double afterSeconds) {
        return new MotionConfig(cycleSeconds, maxJointSpeed, latencyCycles, textPoseCycles, textPoseStep, walkSlowdownFactor, turnGainMin, turnGainMax, walkLeanDeg, beforeSeconds, afterSeconds);
    }

    /** Whole cycles of {@link #standBeforeSeconds}. */
    public int standBeforeCycles() { return (int) Math.round(standBeforeSeconds / cycleSeconds); }

    /** Whole cycles of {@link #standAfterSeconds}. */
    public int standAfterCycles() { return (int) Math.round(standAfterSeconds / cycleSeconds); }

    private static void positive(double v, String name) {
        if (!(v > 0) || !Double.isFinite(v)) throw new IllegalArgumentException(name + " must be > 0, got " + v);
    }
}

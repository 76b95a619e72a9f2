package phalanx.motion.control;

/**
 * The requested-motion variable the agent sets every cycle (4.5.2), with the dynamic elements of
 * 4.5.5. {@code motion} null means "no motion": the playing one is finalized and the joints stop.
 *
 * @param motion    the motion's name in the library, or null
 * @param lean      Walk Leaning, -1 (full right) .. 1 (full left); 0 walks straight
 * @param slowdown  Walk Slowdown: phase durations stretched by the config's factor (about 35 %)
 * @param gain      Turn Gain for text motions, kept within the config's range (0.3 .. 1.0)
 * @param interrupt abort the playing motion now instead of finalizing it (e.g. to stand up after a fall)
 */
public record MotionRequest(String motion, double lean, boolean slowdown, double gain, boolean interrupt) {
    public static final MotionRequest NONE = new MotionRequest(null, 0, false, 1.0, false);

    public MotionRequest {
        if (!Double.isFinite(lean)) throw new IllegalArgumentException("lean must be finite, got " + lean);
        if (!Double.isFinite(gain)) throw new IllegalArgumentException("gain must be finite, got " + gain);
        lean = Math.max(-1, Math.min(1, lean));
    }

    public static MotionRequest of(String motion) { return new MotionRequest(motion, 0, false, 1.0, false); }

    public MotionRequest leaning(double l) { return new MotionRequest(motion, l, slowdown, gain, interrupt); }
    public MotionRequest slowingDown() { return new MotionRequest(motion, lean, true, gain, interrupt); }
    public MotionRequest withGain(double g) { return new MotionRequest(motion, lean, slowdown, g, interrupt); }
    public MotionRequest interrupting() { return new MotionRequest(motion, lean, slowdown, gain, true); }
}

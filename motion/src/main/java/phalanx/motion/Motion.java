package phalanx.motion;

/**
 * A loaded motion: an XML phase motion (4.5.1, {@code phase.PhaseMotion}) or a Webots text motion
 * (4.5.3, {@code webots.TextMotion}). The controller handles exactly these two.
 */
public interface Motion {
    /** The name the agent requests it by (the file name without extension). */
    String name();
    /** Where it was loaded from, for messages. */
    String source();
}

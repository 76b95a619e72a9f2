package phalanx.localization.fall;

/** Thesis 4.6 Stand Up: what the inertial and foot sensors say about the robot's posture. */
public enum FallState {
    /** Upright, or tilted less than the threshold. */
    STANDING,
    /** Inertial values above threshold, not confirmed by the feet yet (a collision looks like this too). */
    FALLING,
    /** Lying face down (the torso's forward axis points at the ground), or on a side. */
    FALLEN_FRONT,
    /** Lying face up: the torso's forward axis points at the sky (by more than LocalizationConfig.fallBackMinDeg). */
    FALLEN_BACK;

    public boolean isDown() { return this == FALLEN_FRONT || this == FALLEN_BACK; }
}

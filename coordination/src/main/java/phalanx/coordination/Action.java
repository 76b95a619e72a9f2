package phalanx.coordination;

/** What a player is told to do (thesis 5.1, 5.5, 5.8). */
public enum Action {
    /** The goalkeeper runs its own behaviour (5.13). */
    GOALKEEPER,
    /** Go to the ball and play it (5.8). */
    ON_BALL,
    /** Go to an active position near the ball (5.8). */
    ACTIVE_POSITION,
    /** Go to a formation position (5.12). */
    SUPPORT_POSITION,
    /** Inactive: "Turn to Localize" until the player knows where it is and stands (5.5). */
    LOCALIZE,
    /** Wait mode: stay put until the kick-off (5.2). */
    WAIT
}

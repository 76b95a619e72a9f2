package phalanx.localization.belief;

/**
 * Counts of what the belief store saw and skipped, since it was made (thesis 4.4 input checks;
 * printed by scripts/phalanx bench localize). A skipped item never throws: it is counted here.
 */
public final class BeliefStats {
    long cycles, visionFrames, selfFixes, selfUpdates, noVision, noLandmark, oneLandmark, badPolar,
            playerWithoutId, fallenFrames, noSide, selfStarts, ballsMissed, staleBallCycles, heardBallCycles, heardBallsMissed;

    public long cycles() { return cycles; }
    /** Cycles that carried a See. */
    public long visionFrames() { return visionFrames; }
    /** Vision frames where pair triangulation gave a fix (two or more landmarks that agree). */
    public long selfFixes() { return selfFixes; }
    /** Vision frames where the filter took the frame (the rest were outliers or had no landmarks). */
    public long selfUpdates() { return selfUpdates; }
    /**
     * Times the self filter began a belief: the first fix, then every re-initialisation (relocation after
     * a move, a FIFO queue emptied by refusals, a start after {@code forgetPose}); each drops the ball.
     */
    public long selfStarts() { return selfStarts; }
    /** Times the ball belief was dropped because the ball was not seen where it was believed, in view (LocalizationConfig.ballMissFrames). */
    public long ballsMissed() { return ballsMissed; }
    /** Cycles with a self pose whose own ball was last seen more than teamBallAfterSeconds ago, or never. */
    public long staleBallCycles() { return staleBallCycles; }
    /** Cycles whose ball belief was the teammates' (the own ball stale; LocalizationConfig.teamBallAfterSeconds). */
    public long heardBallCycles() { return heardBallCycles; }
    /** Times the teammates' ball was dropped: it lay in view and was not seen (as ballsMissed). */
    public long heardBallsMissed() { return heardBallsMissed; }
    public long noVision() { return noVision; }
    public long noLandmark() { return noLandmark; }
    public long oneLandmark() { return oneLandmark; }
    /** Landmark, ball or body-part sightings with a distance of 0, negative or NaN, or a NaN angle. */
    public long badPolar() { return badPolar; }
    public long playerWithoutId() { return playerWithoutId; }
    /** Vision frames skipped for self-localization: the robot was falling or down, or shaken (|acc| far from 1 g). */
    public long fallenFrames() { return fallenFrames; }
    /** Vision frames before the side was known (landmarks cannot be placed in the own frame). */
    public long noSide() { return noSide; }

    /** The share of vision frames with a pair fix. */
    public double fixRate() { return visionFrames == 0 ? 0 : (double) selfFixes / visionFrames; }

    @Override public String toString() {
        return "cycles=" + cycles + " vision=" + visionFrames + " fixes=" + selfFixes + " updates=" + selfUpdates
                + " no_vision=" + noVision + " no_landmark=" + noLandmark + " one_landmark=" + oneLandmark
                + " bad_polar=" + badPolar + " player_without_id=" + playerWithoutId
                + " fallen_frames=" + fallenFrames + " no_side=" + noSide + " self_starts=" + selfStarts + " balls_missed=" + ballsMissed
                + " stale_ball_cycles=" + staleBallCycles + " heard_ball_cycles=" + heardBallCycles + " heard_balls_missed=" + heardBallsMissed;
    }
}

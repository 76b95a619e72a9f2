package phalanx.comm.perception;

/**
 * The GS perceptor. {@code unum} and {@code side} come only in the first message after init
 * (0 and null otherwise); the scores are -1 when absent (servers before 0.7 omit them).
 */
public record GameState(double gameTime, PlayMode playMode, String playModeName,
                        int unum, Side side, int scoreLeft, int scoreRight) {
}

package phalanx.comm.perception;

/**
 * A heard say message. {@code team} is null on servers that do not label messages.
 * {@code self} is true for one's own message; otherwise {@code directionDeg} is the field-frame
 * bearing from the listener to the speaker (in the listener's own frame for a right-side team),
 * not relative to the body (recordings README, S4).
 */
public record Hear(String team, double time, boolean self, double directionDeg, String message) {
}

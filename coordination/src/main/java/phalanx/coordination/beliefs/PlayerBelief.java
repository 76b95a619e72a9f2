package phalanx.coordination.beliefs;

import phalanx.model.field.Vector2;

/**
 * The coordinator's global belief about one player (thesis 5.4).
 *
 * @param id           uniform number
 * @param type         the report it came from (X also for reports that failed validation)
 * @param position     where the player is: reported (C, L), inferred from the ball (B), or null (X)
 * @param headingDeg   body heading in the team's frame, NaN when unknown
 * @param ballDistance distance to the global ball; reported for B; +infinity for X (5.4)
 * @param fallen       the player lies on the ground
 */
public record PlayerBelief(int id, ReportType type, Vector2 position, double headingDeg, double ballDistance,
                           boolean fallen) {
    /** Able to take part in coordination: it knows where it is (or where the ball is) and it stands. */
    public boolean usable() { return position != null && !fallen && Double.isFinite(ballDistance); }
}

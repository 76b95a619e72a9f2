package phalanx.coordination.beliefs;

import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * One player's coordination message (thesis 5.3) as the coordinator holds it, in the team's own frame
 * (own goal at -x). Fields that the report type does not carry are null or NaN.
 *
 * @param id             uniform number
 * @param type           C, L, B or X
 * @param self           own pose (C, L)
 * @param ball           the ball in the team's frame (C)
 * @param ballDistance   metres from the player to the ball (B)
 * @param ballBearingDeg the ball's bearing relative to the body, counter-clockwise (B)
 * @param headingDeg     the body's heading in the team's frame if the player still trusts it (B), else NaN
 * @param fallen         the player lies on the ground: inactive whatever it reports (5.5)
 */
public record PlayerReport(int id, ReportType type, Pose2 self, Vector2 ball, double ballDistance,
                           double ballBearingDeg, double headingDeg, boolean fallen) {

    public PlayerReport {
        if (type == null) throw new IllegalArgumentException("report type is null (player " + id + ")");
    }

    public static PlayerReport complete(int id, Pose2 self, Vector2 ball) {
        return new PlayerReport(id, ReportType.C, self, ball, Double.NaN, Double.NaN, Double.NaN, false);
    }

    public static PlayerReport located(int id, Pose2 self) {
        return new PlayerReport(id, ReportType.L, self, null, Double.NaN, Double.NaN, Double.NaN, false);
    }

    public static PlayerReport ballOnly(int id, double distance, double bearingDeg, double headingDeg) {
        return new PlayerReport(id, ReportType.B, null, null, distance, bearingDeg, headingDeg, false);
    }

    public static PlayerReport lost(int id) {
        return new PlayerReport(id, ReportType.X, null, null, Double.NaN, Double.NaN, Double.NaN, false);
    }

    /** The same report from a player lying on the ground. */
    public PlayerReport asFallen() {
        return new PlayerReport(id, type, self, ball, ballDistance, ballBearingDeg, headingDeg, true);
    }
}

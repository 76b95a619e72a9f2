package phalanx.localization.belief;

import phalanx.comm.perception.Side;
import phalanx.localization.fall.FallState;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * What the agent believes at one cycle; an immutable snapshot the behaviour reads. Positions are in
 * the team's own frame (own goal at -x; for the right side the field turned by 180°), relative
 * vectors in the level body frame (metres from the torso centre, +x forward, +y left).
 *
 * @param self            the self pose (torso), null before the first fix
 * @param selfConfidence  0 (none) to 1, from the filter
 * @param selfAge         seconds since vision last updated the self belief (infinite: never)
 * @param ballRelative    the ball relative to the body, null if never seen
 * @param ballGlobal      the ball in the own frame (filtered, thesis 4.4.3), null without a self belief
 * @param ballAge         seconds since the ball was last seen (infinite: never)
 * @param ballVelocity    Track Moving Object (thesis 4.6), m/s in the own frame, null until enough sightings
 * @param teammates       teammates seen, with their age; not the agent itself
 * @param opponents       opponents seen
 * @param fall            Stand Up's fall state (thesis 4.6)
 * @param ballHeard       the ball fields come from the teammates' reports (thesis 5.4), not from own sight: the own
 *                        ball was not seen for LocalizationConfig.teamBallAfterSeconds; ballAge is then the age of
 *                        the reports and ballVelocity null. Never reported onward as seen (agent's Reports)
 */
public record WorldBelief(double time, Side side, int unum, Pose2 self, double selfConfidence, double selfAge,
                          Vector2 ballRelative, Vector2 ballGlobal, double ballAge, Vector2 ballVelocity,
                          List<PlayerBelief> teammates, List<PlayerBelief> opponents, FallState fall,
                          boolean ballHeard) {

    /** True when the self belief exists and vision refreshed it within the given seconds. */
    public boolean knowsSelf(double maxAgeSeconds) { return self != null && selfAge <= maxAgeSeconds; }

    /** The ball's ground distance from the body, NaN if never seen. */
    public double ballDistance() { return ballRelative == null ? Double.NaN : ballRelative.norm(); }
}

package phalanx.localization.belief;

import phalanx.comm.perception.BodyPart;
import phalanx.localization.field.Vector2;

/**
 * A player seen in vision (thesis 4.4.2): where it is relative to our body (level body frame,
 * +x forward, +y left) and, with a self belief, in the team's own frame; also each seen body part
 * (indexed by {@link BodyPart#ordinal()}, null when not seen). {@code time} is when it was seen.
 */
public record PlayerBelief(String team, int id, double time, Vector2 relative, Vector2 global,
                           Vector2[] partsRelative, Vector2[] partsGlobal) {

    public Vector2 partRelative(BodyPart p) { return partsRelative[p.ordinal()]; }

    public Vector2 partGlobal(BodyPart p) { return partsGlobal == null ? null : partsGlobal[p.ordinal()]; }
}

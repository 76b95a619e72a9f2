package phalanx.localization.belief;

import phalanx.comm.perception.BodyPart;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * A player seen in vision (thesis 4.4.2): where it is relative to our body (level body frame,
 * +x forward, +y left) and, with a self belief, in the team's own frame; also each seen body part
 * (indexed by {@link BodyPart#ordinal()}, null when not seen). {@code time} is when it was seen,
 * {@code seenFrom} our self pose then (null without a self belief): the parts' own-frame positions
 * are made from it on demand, as nothing reads them every cycle.
 */
public record PlayerBelief(String team, int id, double time, Vector2 relative, Vector2 global,
                           Vector2[] partsRelative, Pose2 seenFrom) {

    public Vector2 partRelative(BodyPart p) { return partsRelative[p.ordinal()]; }

    /** The part in the team's own frame, null when not seen or without a self belief. */
    public Vector2 partGlobal(BodyPart p) {
        Vector2 rel = partsRelative[p.ordinal()];
        return seenFrom == null || rel == null ? null : seenFrom.toGlobal(rel);
    }
}

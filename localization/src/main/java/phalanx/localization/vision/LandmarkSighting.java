package phalanx.localization.vision;

import phalanx.comm.perception.Landmark;
import phalanx.model.field.Vector2;

/**
 * One landmark seen in one vision frame: where it is (the team's own frame) and where it was seen,
 * as a ground-plane vector in the level body frame (+x forward, +y left, metres from the torso centre).
 */
public record LandmarkSighting(Landmark landmark, Vector2 position, Vector2 relative) {
}

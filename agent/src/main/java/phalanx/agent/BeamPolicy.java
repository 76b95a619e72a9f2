package phalanx.agent;

import phalanx.comm.perception.PlayMode;
import phalanx.localization.field.Pose2;

/**
 * Beam to the kick-off spot whenever the play mode allows it: before each kick-off and after each
 * goal (both halves). Once per such play mode, and again every 2 s while it lasts, because a beam
 * sent in the cycle the mode changes can be refused.
 */
final class BeamPolicy {
    private static final double REPEAT_S = 2.0;
    private PlayMode lastMode;
    private double lastBeam = Double.NEGATIVE_INFINITY;

    /** The beam to send this cycle, or null. */
    Pose2 beam(PlayMode mode, double now, int unum, int players) {
        if (mode == null || !mode.allowsBeam() || unum < 1) {
            lastMode = mode;
            return null;
        }
        boolean newMode = mode != lastMode;
        lastMode = mode;
        if (!newMode && now - lastBeam < REPEAT_S) return null;
        lastBeam = now;
        double[] spot = KickOffPositions.of(unum, players);
        return new Pose2(spot[0], spot[1], 0);
    }
}

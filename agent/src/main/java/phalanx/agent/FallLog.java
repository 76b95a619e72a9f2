package phalanx.agent;

import phalanx.localization.fall.FallState;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * One log line when the player goes down and one when it stands again, with the game time and how
 * long it was down: scripts/phalanx stats player counts them (falls and get-up times in real games). It stands
 * again only after {@link #STEADY_SECONDS} of STANDING in a row: halfway through a get-up the torso
 * already reads as upright, and a failed try that falls back is the same fall. Rare events, so logging
 * them costs nothing in the cycle.
 */
final class FallLog {
    /** As the get-up bench's success: still upright 1 s later (motion/README.md). */
    static final double STEADY_SECONDS = 1.0;
    private static final Logger LOG = Logger.getLogger(FallLog.class.getName());
    private double downSince = Double.NaN, standingSince = Double.NaN;
    private int falls;

    /** Called every cycle with the belief's fall state; returns the line it logged, or null. */
    String update(FallState fall, double gameTime) {
        if (fall == null) return null;
        String line = null;
        if (fall != FallState.STANDING) standingSince = Double.NaN;
        else if (Double.isNaN(standingSince)) standingSince = gameTime;
        if (fall.isDown() && Double.isNaN(downSince)) {
            downSince = gameTime;
            falls++;
            line = String.format(Locale.ROOT, "fall %d: %s at game time %.2f", falls, fall, gameTime);
        } else if (!Double.isNaN(downSince) && !Double.isNaN(standingSince) && gameTime - standingSince >= STEADY_SECONDS) {
            line = String.format(Locale.ROOT, "fall %d: standing again at game time %.2f after %.2f s", falls, standingSince, standingSince - downSince);
            downSince = Double.NaN;
        }
        if (line != null) LOG.info(line);
        return line;
    }

    int falls() { return falls; }
}

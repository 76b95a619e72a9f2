package phalanx.agent;

import phalanx.localization.fall.FallState;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * One log line when the player goes down and one when it stands again, with the game time and how
 * long it lay: scripts/player-stats counts them (falls and get-up times in real games). Rare events,
 * so logging them costs nothing in the cycle.
 */
final class FallLog {
    private static final Logger LOG = Logger.getLogger(FallLog.class.getName());
    private double downSince = Double.NaN;
    private int falls;

    /** Called every cycle with the belief's fall state; returns the line it logged, or null. */
    String update(FallState fall, double gameTime) {
        if (fall == null) return null;
        String line = null;
        if (fall.isDown() && Double.isNaN(downSince)) {
            downSince = gameTime;
            falls++;
            line = String.format(Locale.ROOT, "fall %d: %s at game time %.2f", falls, fall, gameTime);
        } else if (fall == FallState.STANDING && !Double.isNaN(downSince)) {
            line = String.format(Locale.ROOT, "fall %d: standing again at game time %.2f after %.2f s", falls, gameTime, gameTime - downSince);
            downSince = Double.NaN;
        }
        if (line != null) LOG.info(line);
        return line;
    }

    int falls() { return falls; }
}

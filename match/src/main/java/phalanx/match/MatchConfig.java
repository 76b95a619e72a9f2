package phalanx.match;

import java.nio.file.Path;

/**
 * One match to run. {@code first} starts first and so normally plays on the left. Times in seconds:
 * {@code connectTimeout} per team to get its players onto the field, {@code settle} between the last
 * player and the kick-off (beams), {@code stall} without a monitor message before the game is given up.
 */
public record MatchConfig(TeamCommand first, TeamCommand second, ServerProcess.Settings server, int players,
                          double connectTimeout, double connectQuiet, double settle, double stall,
                          double maxWall, Path dir, Path out, Path workDir, boolean allowEmpty) {

    /** The wall-clock limit when none is given: six times the game length plus the start-up. */
    public static double defaultMaxWall(ServerProcess.Settings s, double connectTimeout) {
        return 6 * s.halfTime() * s.halves() + 2 * connectTimeout + 120;
    }
}

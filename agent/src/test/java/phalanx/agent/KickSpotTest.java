package phalanx.agent;

import org.junit.jupiter.api.Test;
import phalanx.motion.MotionLibrary;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Each robot type prepares its kicks at the ball spot the kick file it plays was tuned for: the spot
 * its description states ("Ball X m ahead of the torso, Y m right", written by scripts/phalanx bench kick-search).
 * A re-tuned file with a new spot and a config left behind would strike the ball early (motion/README.md).
 */
class KickSpotTest {
    private static final Pattern SPOT = Pattern.compile("Ball ([\\d.]+) m ahead of the torso, ([\\d.]+) m right");

    @Test
    void everyTypePreparesItsKicksAtTheSpotsOfTheFilesItPlays() throws Exception {
        Path dir = Path.of("motions"); // the build runs tests from the project root
        for (int type = 0; type <= 4; type++) {
            MotionLibrary lib = MotionLibrary.load(dir, type);
            AgentConfig.Kick k = AgentConfig.forRobotType(type).kick();
            for (boolean strong : new boolean[] {false, true}) {
                String file = lib.get(strong ? "strong_kick" : "kick").source();
                Matcher m = SPOT.matcher(Files.readString(Path.of(file)));
                assertTrue(m.find(), file + " states no ball spot");
                String what = "type " + type + ", " + file;
                assertEquals(Double.parseDouble(m.group(1)), k.spotX(strong), 1e-9, what);
                assertEquals(-Double.parseDouble(m.group(2)), k.spotY(strong, false), 1e-9, what);
            }
        }
    }
}

package phalanx.match;

import org.junit.jupiter.api.Test;
import phalanx.comm.recording.Recordings;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/** game-watch's line on the monitor stream recorded from the real server (M1, recordings README; skips without it). */
class GameWatchTest {
    @Test
    void linesShowTheBallAndTheRobotAsTheRecordedRunMovedThem() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        List<String> lines = Files.readAllLines(Recordings.dir().get().resolve("M1_monitor.txt"), StandardCharsets.ISO_8859_1);
        GameWatch w = new GameWatch(11);
        for (String l : lines.subList(0, 3)) assertTrue(w.apply(l));
        String first = w.line();
        assertTrue(first.contains(" ball=(0.00,0.00)"), first);
        assertTrue(first.contains(" L1(-14.2,9.2)") && !first.contains("L1(-14.2,9.2)_"), "spawned upright: " + first);
        assertFalse(first.contains(" L2(") || first.contains(" R1("), first);
        boolean sawBall = false;
        for (String l : lines.subList(3, lines.size())) {
            w.apply(l);
            if (w.line().contains(" ball=(2.00,1.00)")) sawBall = true;   // the trainer's (ball (pos 2 1 0.042))
        }
        assertTrue(sawBall);
        assertFalse(w.apply("((time 1.0)(RSG 0 1)((nd TRF (SLT 1 0"), "a truncated message is skipped, not fatal");
    }
}

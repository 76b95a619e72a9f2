package phalanx.match;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** MjMonitor over the real monitor recording (match/src/test/resources/rcssservermj/README.md). */
class MjMonitorTest {
    private static final Path RECORDING = Path.of("match/src/test/resources/rcssservermj/monitor-kickoff.txt");

    @Test
    void followsTheRecordedKickOff() throws Exception {
        List<String> lines = Files.readAllLines(RECORDING);
        MjMonitor m = new MjMonitor();
        MjMonitor.State first = m.accept(lines.get(0));
        assertEquals("BeforeKickOff", first.playMode());
        assertEquals(0, first.time(), 1e-9);
        assertEquals(1, first.half());
        assertEquals("Alpha", first.teamLeft());
        assertNull(first.teamRight(), "<RIGHT>: nobody on the right yet");
        MjMonitor.State last = first;
        boolean namedBeta = false;
        for (String line : lines.subList(1, lines.size())) {
            MjMonitor.State s = m.accept(line);
            assertTrue(s.time() >= last.time(), "time runs forward");
            namedBeta |= "Beta".equals(s.teamRight());
            last = s;
        }
        assertTrue(namedBeta, "the right team named in a later full state");
        assertEquals("KickOff_Left", last.playMode());
        assertTrue(last.time() > 0.2, "the clock runs after the kick-off: " + last.time());
        assertEquals(0, last.scoreLeft() + last.scoreRight());
        assertFalse(last.gameOver());
    }

    @Test
    void theServersOwnModeListMatchesTheBuiltInOneAStateBeforeItIsNamed() throws Exception {
        String first = Files.readAllLines(RECORDING).get(0);
        int at = first.indexOf("(play_modes ") + 12;
        assertEquals(MjMonitor.DEFAULT_MODES, List.of(first.substring(at, first.indexOf(')', at)).split(" ")));
        assertEquals("PlayOn", new MjMonitor().accept("((gs 1 0)(time 1.0)(half 1)(score_left 0)(score_right 0)(play_mode 3))").playMode());
    }

    @Test
    void aTruncatedOrForeignMessageKeepsTheLastState() throws Exception {
        List<String> lines = Files.readAllLines(RECORDING);
        MjMonitor m = new MjMonitor();
        MjMonitor.State s = m.accept(lines.get(0));
        String cut = lines.get(5).substring(0, lines.get(5).indexOf("(gs 1 0)") + 20);
        assertSame(s, m.accept(cut));
        assertSame(s, m.accept("((RSMP 1 0)((gt 1 0)3.0))"));
        assertSame(s, m.accept(""));
        MjMonitor.State bad = m.accept("((gs 1 0)(time x)(half 1)(score_left 0)(score_right 0)(play_mode 99))");
        assertTrue(Double.isNaN(bad.time()));
        assertEquals("mode 99", bad.playMode(), "an index beyond the list is named, not thrown");
    }

    @Test
    void theBallsPlaceFromFullStatesAndFromTheDiffsThatMoveIt() throws Exception {
        List<String> lines = Files.readAllLines(RECORDING);
        double[] first = MjMonitor.ball(lines.get(0));
        assertArrayEquals(new double[]{0, 0, 0.1097}, first, 1e-9, "the ball dropped on the centre spot");
        int moved = 0;
        for (String line : lines.subList(1, lines.size())) {
            double[] b = MjMonitor.ball(line);
            if (b == null) continue;   // a diff that leaves the ball where it was
            moved++;
            assertEquals(0, Math.hypot(b[0], b[1]), 0.01, "nobody touched it: " + java.util.Arrays.toString(b));
            assertEquals(0.11, b[2], 0.005, "on the ground (radius 0.11)");
        }
        assertTrue(moved > 0, "some message places it again");
        assertNull(MjMonitor.ball("((RSMP 1 0)((gt 1 0)1.0)((gs 1 0)(time 0)))"), "no scene graph");
        assertNull(MjMonitor.ball(lines.get(0).substring(0, 200)), "cut inside the ball's transform");
    }

    @Test
    void rosterFromTheServerLog() {
        List<String[]> r = MjMonitor.rosterLines(List.of("[INFO] Starting server...",
                "[INFO] Player Alpha #1 joined the game.", "[INFO] Player Beta Two #7 joined the game.",
                "[INFO] Player Alpha #1 left the game."));
        assertEquals(3, r.size());
        assertArrayEquals(new String[] {"Beta Two", "7", "joined"}, r.get(1));
        assertArrayEquals(new String[] {"Alpha", "1", "left"}, r.get(2));
    }
}

package phalanx.bench.record;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The recorder's flags and the scenarios' frames (the recordings themselves are checked by LocalizeEvalFixturesTest). */
class RecorderTest {
    @Test
    void flags() {
        Recorder.Options o = Recorder.parse("crowd", "--dir", "/tmp/x", "--type", "4", "--side", "right", "--port", "4600");
        assertEquals(new Recorder.Options("crowd", Path.of("/tmp/x"), "crowd", 4, true, 4600), o);
        assertEquals("walk-head-right", Recorder.parse("walk-head", "--dir", "d", "--name", "walk-head-right").name());
        assertEquals(-1, Recorder.parse("fall", "--dir", "d").type(), "the scenario's own type");
    }

    @Test
    void badFlagsAreNamed() {
        assertEquals("no scenario (one of walk-head, turn-head, ball-roll, crowd, fall)", msg("--dir", "d"));
        assertEquals("unknown scenario 'dance' (one of walk-head, turn-head, ball-roll, crowd, fall)", msg("dance", "--dir", "d"));
        assertEquals("--dir is required", msg("fall"));
        assertEquals("--type must be 0-4, got 5", msg("fall", "--dir", "d", "--type", "5"));
        assertEquals("--type needs a number, got 'x'", msg("fall", "--dir", "d", "--type", "x"));
        assertEquals("--side must be left or right, got 'up'", msg("fall", "--dir", "d", "--side", "up"));
        assertEquals("--name takes letters, digits, '_', '.', '-', got 'a/b'", msg("fall", "--dir", "d", "--name", "a/b"));
        assertEquals("unknown option --speed", msg("fall", "--dir", "d", "--speed", "2"));
        assertEquals("--port needs a value", msg("fall", "--dir", "d", "--port"));
        assertEquals("one scenario only, got 'fall' and 'crowd'", msg("fall", "crowd", "--dir", "d"));
    }

    private static String msg(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> Recorder.parse(args)).getMessage();
    }

    @Test
    void theOtherTeamBeamsInItsOwnFrameAndTheTrainerMirrorsOnTheRight() {
        // crowd: the first opponent stands at (1.0, 0.6) of the recorded team's frame facing it (180°): in its own frame (-1.0, -0.6) facing 0°
        Scenario left = Scenario.of("crowd", false);
        Plan first = left.others().get(0).plan();
        assertEquals(-1.0, first.beamX(), 1e-12);
        assertEquals(-0.6, first.beamY(), 1e-12);
        assertEquals(0.0, first.beamDeg(), 1e-12);
        assertEquals(List.of("(playMode PlayOn)"), left.trainer().get(30));
        assertEquals(List.of("(ball (pos 1.5 0 0.042) (vel 0 0 0))"), left.trainer().get(32));
        // on the right the trainer's field coordinates are the recorded team's turned by 180°; the beams do not change
        Scenario right = Scenario.of("crowd", true);
        assertEquals(List.of("(ball (pos -1.5 0 0.042) (vel 0 0 0))"), right.trainer().get(32));
        assertEquals(List.of("(ball (pos 0 5 0.042) (vel 0 -7 0))"), Scenario.of("ball-roll", true).trainer().get(100));
        assertEquals(first, right.others().get(0).plan());
    }

    @Test
    void aPlanLastsItsStepsAndItsHeadFollowsItsLaw() {
        Plan p = Plan.at(0, 0, 0).pan(90, 4).tilt(-10, 35, 2.6).stand(1).walk(2, 0.5, 0, 0).tip(-2).getUp().build();
        assertEquals(50 + 100 + 25 + 400, p.cycles());
        assertEquals(90, p.headYawDeg(1.0), 1e-9, "a quarter period: the full pan");
        assertEquals(-10, p.headPitchDeg(0), 1e-9);
        assertEquals(25, p.headPitchDeg(0.65), 1e-9, "a quarter of 2.6 s: -10 + 35");
    }
}

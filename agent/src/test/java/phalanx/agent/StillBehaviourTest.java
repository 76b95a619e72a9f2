package phalanx.agent;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.recording.Recordings;
import phalanx.comm.sexp.PerceptionParser;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * {@code --behaviour still}, the "empty" goalkeeper of thesis 6.3: over the recorded S2 stream (PlayOn,
 * ball in sight; needs ../shared/recordings, skipped with a message when missing) its head only ever
 * returns to straight ahead, while the real goalkeeper looks around.
 */
class StillBehaviourTest {
    private static final Pattern HE1 = Pattern.compile("\\(he1 (-?[0-9.eE-]+)\\)");
    private static List<String> s2;

    @BeforeAll
    static void load() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        s2 = Recordings.perceptorMessages(Recordings.named("S2"));
    }

    /** Cycles in which the head pan is commanded away from 0 by more than a hair. */
    private static int headMovesAway(String... flags) throws Exception {
        PlayerOptions o = PlayerOptions.parse(flags);
        PlayerRuntime runtime = new PlayerRuntime(o, Player.parts(o));
        PerceptionParser parser = new PerceptionParser();
        int away = 0;
        for (int i = 1; i < s2.size(); i++) {
            byte[] m = s2.get(i).getBytes(StandardCharsets.ISO_8859_1);
            double pan = parser.parse(m, 0, m.length).joints().degrees(Joint.HJ1);
            Matcher v = HE1.matcher(runtime.update(m, m.length));
            if (v.find() && Double.parseDouble(v.group(1)) * pan > 0 && Math.abs(pan) > 0.5) away++;
            if (v.find(0) && Math.abs(pan) <= 0.5 && Math.abs(Double.parseDouble(v.group(1))) > 0.5) away++;
        }
        return away;
    }

    @Test
    void theStillKeeperOnlyTurnsItsHeadBackToStraight() throws Exception {
        assertEquals(0, headMovesAway("--unum", "1", "--team", "Phalanx", "--behaviour", "still"));
        assertTrue(headMovesAway("--unum", "1", "--team", "Phalanx") > 10, "the playing keeper looks around");
    }

    @Test
    void behaviourFlagIsChecked() {
        assertTrue(PlayerOptions.parse("--behaviour", "still").still());
        assertFalse(PlayerOptions.parse("--behaviour", "play").still());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PlayerOptions.parse("--behaviour", "lazy"));
        assertEquals("--behaviour must be play or still, got 'lazy'", e.getMessage());
    }
}

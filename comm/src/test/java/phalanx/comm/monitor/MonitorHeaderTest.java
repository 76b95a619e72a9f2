package phalanx.comm.monitor;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.recording.Recordings;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

class MonitorHeaderTest {

    @Test
    void foldsChangesIntoTheState() {
        MonitorHeader h = new MonitorHeader();
        MatchState s = h.apply(MatchState.INITIAL, "((time 0)(half 1)(score_left 0)(score_right 0)(play_mode 0))(RSG 0 1)(...)");
        s = h.apply(s, "((time 61.3)(play_mode 3)(team_left Phalanx)(team_right Other))(RDS 0 1)()");
        s = h.apply(s, "((time 70.02)(score_left 1)(play_mode 14))(RDS 0 1)()");
        assertEquals(70.02, s.time(), 1e-9);
        assertEquals(1, s.scoreLeft());
        assertEquals(PlayMode.GOAL_RIGHT, s.playMode());
        assertEquals("Phalanx", s.teamLeft());
        assertEquals(s, h.apply(s, "((time abc))(RDS)"), "a malformed header changes nothing");
        assertEquals(s, h.apply(s, "garbage"));
    }

    @Test
    void m1MonitorStreamFollowsTheTrainerCommands() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        // M1_trainer.txt: (kickOff Left) at 3.62, (playMode PlayOn) at 4.62; the stream shows KickOff_Left then PlayOn.
        List<String> lines = Files.readAllLines(Recordings.dir().get().resolve("M1_monitor.txt"), StandardCharsets.ISO_8859_1);
        MonitorHeader h = new MonitorHeader();
        MatchState s = MatchState.INITIAL;
        boolean sawKickOff = false;
        for (String l : lines) {
            s = h.apply(s, l);
            if (s.playMode() == PlayMode.KICK_OFF_LEFT) sawKickOff = true;
        }
        assertTrue(sawKickOff);
        assertEquals(PlayMode.PLAY_ON, s.playMode());
        assertEquals(0, s.scoreLeft());
        assertTrue(s.time() > 0);
    }
}

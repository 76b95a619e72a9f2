package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.match.MatchResult.TeamResult;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class MatchResultTest {
    @TempDir Path dir;

    static MatchResult sample() {
        TeamResult a = new TeamResult("Us", "Phalanx", "scripts/start.sh {host} {port}", "left", 0, "ok", 0,
                List.of(1, 2), List.of(), List.of(), null, "/tmp/Us.log");
        TeamResult b = new TeamResult("Them", "Them", "./start.sh {host} -p {port}", "right", 2, "incomplete", 0,
                List.of(1), List.of(2), List.of(), null, "/tmp/Them.log");
        return new MatchResult(true, null, "2024-01-01T00:00:00Z", 200.5, 150.0,
                new MatchResult.ServerInfo(3500, 3600, true, true, "/tmp/server.log", 0, false), 60, 2, 120.0, a, b,
                List.of(new MatchResult.Goal(12.3, 1, "right", "Them", 0, 1)), List.of(new MatchResult.ModeChange(0, 1, "BeforeKickOff")),
                List.of(new MatchResult.RosterEvent(0, 1, "left", 1, true)));
    }

    @Test
    void roundTripsThroughJson() throws IOException {
        Path f = dir.resolve("game-01.json");
        sample().write(f);
        assertEquals(sample(), MatchResult.read(f));
        assertTrue(Files.readString(f).contains("\"neverConnected\" : [ 2 ]"));
    }

    @Test
    void aFileThatIsNotAResultIsNamed() throws IOException {
        Path f = dir.resolve("game-02.json");
        Files.writeString(f, "{\"completed\": true");
        IOException e = assertThrows(IOException.class, () -> MatchResult.read(f));
        assertTrue(e.getMessage().startsWith(f + " is not a match result"), e.getMessage());
        Files.writeString(f, "{\"completed\": true}");
        assertTrue(assertThrows(IOException.class, () -> MatchResult.read(f)).getMessage().contains("no left or right team"));
    }

    @Test
    void teamStatusFromTheFacts() {
        assertEquals("failed-to-start", TeamResult.status(0, 0, 11, 0, 127));
        assertEquals("never-connected", TeamResult.status(0, 0, 11, 0, 0));
        assertEquals("never-connected", TeamResult.status(0, 0, 11, 0, null));
        assertEquals("crashed", TeamResult.status(11, 0, 0, 11, 0));
        assertEquals("incomplete", TeamResult.status(9, 9, 2, 0, 0));
        assertEquals("incomplete", TeamResult.status(11, 10, 0, 1, 0));
        assertEquals("ok", TeamResult.status(11, 11, 0, 0, 0));
    }

    @Test
    void gameForTheTablesCarriesLabelsScoreAndNotes() {
        Standings.Game g = Standings.Game.of(sample());
        assertEquals(new Standings.Game("Us", "Them", 0, 2, true, "Them incomplete"), g);
    }
}

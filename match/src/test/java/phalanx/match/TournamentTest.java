package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.match.Tournament.Fixture;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class TournamentTest {
    @TempDir Path dir;
    private final List<TeamCommand> teams = List.of(TeamCommand.parse("P=a {port}"), TeamCommand.parse("U=b {port}"),
            TeamCommand.parse("F=c {port}"));

    private static String names(List<Fixture> fs) {
        StringBuilder sb = new StringBuilder();
        for (Fixture f : fs) sb.append(f.first().label()).append(f.second().label()).append(' ');
        return sb.toString().trim();
    }

    @Test
    void opponentsNGamesEachWithAlternatingSides() {
        assertEquals("PU UP PF FP", names(Tournament.schedule(teams, "P", 2, false)));
        assertEquals("UP UF", names(Tournament.schedule(teams, "U", 1, false)));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Tournament.schedule(teams, "Q", 1, false))
                .getMessage().contains("--us Q"));
    }

    @Test
    void roundRobinPlaysEveryPair() {
        assertEquals("PU PF UF UP FP FU", names(Tournament.schedule(teams, "P", 2, true)));
    }

    @Test
    void reportReadsResultsAndWritesTablesAndPlot() throws IOException {
        MatchResultTest.sample().write(dir.resolve("game-01.json"));
        Files.writeString(dir.resolve("notes.json"), "ignored: not game-NN.json");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        Tournament.report(dir, "Us", new PrintStream(out, true));
        String text = out.toString();
        assertTrue(text.contains("| Them | 0 | 0 | 1 | -2.00 (± 0.00) | 1 | 0 |"), text);
        assertTrue(text.contains("| 1 | Them | 1 | 1 | 0 | 0 | 2 | 0 | 3 |"), text);
        assertTrue(Files.exists(dir.resolve("goal-difference.svg")));
        assertTrue(Files.readString(dir.resolve("tables.md")).contains("Table 6.5"));
        assertTrue(Tournament.progressLine(1, 4, MatchResultTest.sample()).startsWith("[1/4] Us 0:2 Them  (completed"));
    }

    @Test
    void reportOfAFolderWithoutResultsSaysSo() {
        IOException e = assertThrows(IOException.class, () -> Tournament.report(dir, "Us", new PrintStream(new ByteArrayOutputStream())));
        assertTrue(e.getMessage().contains("no game-NN.json results in"));
    }
}

package phalanx.match;

import org.junit.jupiter.api.Test;
import phalanx.match.Standings.Game;
import phalanx.match.Standings.LeagueRow;
import phalanx.match.Standings.OpponentRow;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class StandingsTest {
    // Us against X: 2:0 (left), 1:1 (right), 0:3 (right, so X scored 3); against Y: 1:0, and one game that did not finish.
    private final List<Game> games = List.of(
            new Game("Us", "X", 2, 0, true, ""),
            new Game("X", "Us", 1, 1, true, ""),
            new Game("X", "Us", 3, 0, true, ""),
            new Game("Us", "Y", 1, 0, true, ""),
            new Game("Y", "Us", 5, 0, false, "server died"));

    @Test
    void table64PerOpponent() {
        List<OpponentRow> rows = Standings.versus("Us", games);
        assertEquals(2, rows.size());
        OpponentRow x = rows.get(0);
        assertEquals("X", x.opponent());
        assertEquals(List.of(1, 1, 1), List.of(x.won(), x.drawn(), x.lost()));
        assertEquals(List.of(2, 0, -3), x.differences());
        assertEquals(-1.0 / 3, x.averageDifference(), 1e-12);
        // sample sd of 2, 0, -3 around -1/3: sqrt((49/9 + 1/9 + 64/9) / 2) = sqrt(19/3)
        assertEquals(Math.sqrt(19.0 / 3), x.spread(), 1e-12);
        assertEquals(3, x.games());
        OpponentRow y = rows.get(1);
        assertEquals(1, y.won());
        assertEquals(1, y.games());
        assertEquals(1, y.notCounted(), "the unfinished game is not a result");
        assertEquals(1.0, y.averageDifference(), 1e-12);
        assertTrue(Standings.table64("Us", rows).contains("| X | 1 | 1 | 1 | -0.33 (± 2.52) | 3 | 0 |"), Standings.table64("Us", rows));
    }

    @Test
    void table65LeagueWithThreeOneZeroPoints() {
        List<LeagueRow> rows = Standings.league(games);
        // Us: W2 D1 L1, F 4 A 4, 7 pts; X: W1 D1 L1, F 4 A 3, 4 pts; Y: L1, F0 A1, 0 pts
        assertEquals(new LeagueRow("Us", 4, 2, 1, 1, 4, 4, 7), rows.get(0));
        assertEquals(new LeagueRow("X", 3, 1, 1, 1, 4, 3, 4), rows.get(1));
        assertEquals(new LeagueRow("Y", 1, 0, 0, 1, 0, 1, 0), rows.get(2));
        assertTrue(Standings.table65(rows).contains("| 1 | Us | 4 | 2 | 1 | 1 | 4 | 4 | 7 |"));
    }

    @Test
    void tiesOnPointsGoByGoalDifferenceThenGoals() {
        List<LeagueRow> rows = Standings.league(List.of(new Game("A", "B", 1, 1, true, ""), new Game("C", "D", 3, 3, true, ""),
                new Game("A", "C", 0, 0, true, "")));
        // C and A: 2 pts, GD 0, but C scored 3 and A 1; D and B: 1 pt, GD 0, D scored 3 and B 1
        assertEquals(List.of("C", "A", "D", "B"), rows.stream().map(LeagueRow::team).toList());
    }

    @Test
    void plotHasOneDotPerCountedGame() {
        String svg = GoalDifferencePlot.svg("Us", Standings.versus("Us", games));
        assertTrue(svg.startsWith("<svg"));
        assertEquals(4, svg.split("<circle").length - 1);
        assertTrue(svg.contains(">X<") && svg.contains(">Y<"));
        assertTrue(svg.contains("1 game +1 n/c"));
    }
}

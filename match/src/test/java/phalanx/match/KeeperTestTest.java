package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.match.MatchResult.TeamResult;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class KeeperTestTest {
    @TempDir Path dir;

    /** One half; the defender may have had no player at all (side null) and the attacker then took the left. */
    private static MatchResult half(String defender, boolean defenderLeft, int conceded, boolean completed) {
        return half(defender, defenderLeft, conceded, completed, 300.0);
    }

    private static MatchResult half(String defender, boolean defenderLeft, int conceded, boolean completed, double gameTime) {
        TeamResult d = new TeamResult(defender, defender.equals("NoKeeper") ? null : "Phalanx", "x {port}",
                defender.equals("NoKeeper") ? null : (defenderLeft ? "left" : "right"), 0,
                defender.equals("NoKeeper") ? "never-connected" : "ok", 0, List.of(), List.of(), List.of(), null, "/tmp/d.log");
        TeamResult a = new TeamResult("FCP", "FCPortugal", "y {port}", defenderLeft ? "right" : "left", conceded, "ok", 0,
                List.of(1), List.of(), List.of(), null, "/tmp/a.log");
        return new MatchResult(completed, completed ? null : "server stalled", "2026-11-22T00:00:00Z", 400, 300.0,
                new MatchResult.ServerInfo(3500, 3600, true, true, "/tmp/s.log", 0, false), 300, 1, gameTime,
                defenderLeft ? d : a, defenderLeft ? a : d, List.of(), List.of(), List.of());
    }

    @Test
    void tableCountsTheAttackersGoalsPerCompletedHalf() throws IOException {
        half("NoKeeper", false, 6, true).write(dir.resolve("none-01.json"));
        half("NoKeeper", false, 8, true).write(dir.resolve("none-02.json"));
        half("Keeper", true, 2, true).write(dir.resolve("keeper-01.json"));
        half("Keeper", true, 9, false).write(dir.resolve("keeper-02.json"));   // not completed: not counted
        String table = KeeperTest.report(dir);
        assertTrue(table.contains("| NoKeeper | 2 | [6, 8] | 7.0 | 7 | 0 |"), table);
        assertTrue(table.contains("| Keeper | 1 | [2] | 2.0 | 3 | 1 |"), table);
        assertFalse(table.contains("StillKeeper"), "a condition not played has no row");
        assertEquals(table.substring(0, table.indexOf("\n(")).stripTrailing(), Files.readString(dir.resolve("table.md")).stripTrailing());
    }

    @Test
    void aStartThatNeverKickedOffIsSetAsideAndLeavesTheTable() throws IOException {
        assertTrue(KeeperTest.neverKickedOff(half("StillKeeper", true, 0, false, 0.0)), "stalled at game time 0");
        assertTrue(KeeperTest.neverKickedOff(half("StillKeeper", true, 0, false, 0.04)), "stalled at the kick-off (seen)");
        assertFalse(KeeperTest.neverKickedOff(half("StillKeeper", true, 2, false, 120.0)), "stalled mid-game: a result to report");
        assertFalse(KeeperTest.neverKickedOff(half("StillKeeper", true, 4, true)));
        half("StillKeeper", true, 0, false, 0.0).write(dir.resolve("still-01.json"));
        Files.createDirectories(dir.resolve("still-01"));
        KeeperTest.setAside(dir, "still-01", 1);
        assertTrue(Files.exists(dir.resolve("still-01.stall1.json")));
        assertTrue(Files.isDirectory(dir.resolve("still-01.stall1")));
        assertFalse(Files.exists(dir.resolve("still-01")));
        half("StillKeeper", true, 4, true).write(dir.resolve("still-01.json"));
        String table = KeeperTest.report(dir);
        assertTrue(table.contains("| StillKeeper | 1 | [4] | 4.0 | 7 | 0 |"), table);
    }

    @Test
    void unknownConditionIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> KeeperTest.conditions("none,goalie"));
        assertEquals("keeper-test: unknown condition 'goalie' (none, still, keeper)", e.getMessage());
    }

    @Test
    void emptyFolderSaysSo() {
        IOException e = assertThrows(IOException.class, () -> KeeperTest.report(dir));
        assertTrue(e.getMessage().startsWith("no <condition>-NN.json results in"));
    }
}

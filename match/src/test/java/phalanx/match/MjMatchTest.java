package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * A whole two-half match on the real rcssservermj between two stand-in teams (one T1 each that only answers
 * (syn): match/src/test/resources/rcssservermj/syn-agent.py). Needs rcssservermj (scripts/setup.sh); skips
 * without it.
 */
class MjMatchTest {
    private static final String AGENT = Path.of("match/src/test/resources/rcssservermj/syn-agent.py").toAbsolutePath().toString();

    @Test
    void aConfigTheServerCannotPlayIsRefusedWithTheReason() {
        TeamCommand a = new TeamCommand("Alpha", "x {port}"), b = new TeamCommand("Beta", "y {port}");
        Path exe = Path.of("/x/rcssservermj"), dir = Path.of("/tmp/x");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new MjMatch.Config(exe, a, b, 3970, 4070, 301, 2, 7, 60, dir, dir.resolve("r.json")));
        assertTrue(e.getMessage().contains("1-300 s"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new MjMatch.Config(exe, a, b, 3970, 4070, 60, 3, 7, 60, dir, dir));
        assertTrue(e.getMessage().contains("halves must be 1 or 2"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new MjMatch.Config(exe, a, a, 3970, 4070, 60, 2, 7, 60, dir, dir));
        assertTrue(e.getMessage().contains("both teams are called Alpha"), e.getMessage());
    }

    @Test
    void playsBothHalvesRecordsTheResultAndStopsEveryProcess(@TempDir Path tmp) throws Exception {
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        assumeTrue(exe.isPresent(), "rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
        int port = ServerProcess.freePortPair(3970);
        TeamCommand a = new TeamCommand("Alpha", "python3 " + AGENT + " {host} {port} Alpha 1");
        TeamCommand b = new TeamCommand("Beta", "python3 " + AGENT + " {host} {port} Beta 1");
        Path out = tmp.resolve("result.json");
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        MjMatch m = new MjMatch(new MjMatch.Config(exe.get(), a, b, port, port + 100, 2, 2, 1, 60, tmp, out),
                new PrintStream(progress, true));
        MatchResult r = m.run();
        String said = progress.toString();
        assertTrue(r.completed(), r.reason() + "\n" + said);
        assertEquals(r.toJson().trim(), Files.readString(out).trim(), "the result is written");
        List<String> modes = r.playModes().stream().map(MatchResult.ModeChange::mode).toList();
        assertTrue(modes.containsAll(List.of("KickOff_Left", "KickOff_Right", "GameOver")), modes.toString());
        assertEquals(600, r.gameTime(), 0.05, "the second half ends at 600 s of play time");
        assertEquals(List.of(1), r.left().connected());
        assertEquals(List.of(1), r.right().connected());
        assertEquals("ok", r.left().status());
        assertEquals("Alpha", r.left().team());
        assertEquals("Beta", r.right().team());
        assertTrue(said.contains("game over: Alpha 0:0 Beta"), said);
        for (Path log : List.of(tmp.resolve("half-1/server.log"), tmp.resolve("half-2/server.log"))) {
            assertTrue(Files.readString(log).contains("Shutting down server... DONE!"), "server stopped: " + log);
        }
        assertTrue(Files.size(tmp.resolve("half-2/monitor.log.gz")) > 0);
        assertFalse(ProcessHandle.allProcesses().anyMatch(p -> p.info().commandLine().orElse("").contains(AGENT + " 127.0.0.1 " + port)),
                "no stand-in team left running");
    }
}

package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.OptionalLong;

import static org.junit.jupiter.api.Assertions.*;

class SessionProcessTest {
    @TempDir Path dir;

    private static void waitUntil(java.util.function.BooleanSupplier c) throws InterruptedException {
        for (int i = 0; i < 100 && !c.getAsBoolean(); i++) Thread.sleep(50);
    }

    /** An orphan that was stopped may stay a zombie until init reaps it: it runs no more. */
    private static boolean goneOrZombie(long pid) {
        try {
            String stat = Files.readString(Path.of("/proc/" + pid + "/stat"));
            return stat.substring(stat.lastIndexOf(')') + 2).startsWith("Z");
        } catch (java.io.IOException e) {
            return true;
        }
    }

    @Test
    void aTeamCommandThatDoesNotExistExitsWith127AndLeavesNothing() throws Exception {
        Path log = dir.resolve("team.log");
        SessionProcess p = SessionProcess.shell("/no/such/start.sh 127.0.0.1 3500", dir, log, "bad");
        waitUntil(() -> p.exitCode() != null);
        assertEquals(127, p.exitCode());
        assertFalse(p.anyAlive());
        assertTrue(Files.readString(log).contains("No such file"), "the shell's message is in the team's log");
    }

    @Test
    void playersLeftInTheBackgroundAreFoundAndStoppedByPid() throws Exception {
        // like a team start script: puts its players in the background and exits at once
        SessionProcess p = SessionProcess.shell("sleep 60 & sleep 60 & exit 0", dir, dir.resolve("t.log"), "team");
        waitUntil(() -> p.exitCode() != null && p.members().size() == 2);
        assertEquals(0, p.exitCode());
        List<Long> players = p.members();
        assertEquals(2, players.size(), "both background sleeps are in the session");
        for (long pid : players) assertEquals(OptionalLong.of(p.pid()), SessionProcess.sessionOf(Files.readString(Path.of("/proc/" + pid + "/stat"))));
        assertEquals(0, p.stop("TERM", 3000), "SIGTERM was enough");
        assertFalse(p.anyAlive());
        for (long pid : players) assertTrue(goneOrZombie(pid), "player " + pid + " is stopped");
    }

    @Test
    void aProcessThatIgnoresTheFirstSignalIsKilled() throws Exception {
        SessionProcess p = SessionProcess.shell("trap '' INT TERM; sleep 60 & trap '' INT TERM; wait", dir, dir.resolve("t.log"), "stubborn");
        waitUntil(() -> p.members().size() == 2);
        assertTrue(p.stop("INT", 300) >= 1, "what ignored SIGINT needed SIGKILL");
        assertFalse(p.anyAlive());
    }

    @Test
    void sessionIdIsReadAfterTheCommandName() {
        assertEquals(OptionalLong.of(4242), SessionProcess.sessionOf("77 (we ird) name)) S 1 4242 4242 0 -1 4194560 ..."));
        assertEquals(OptionalLong.empty(), SessionProcess.sessionOf("garbage"));
        assertEquals(OptionalLong.empty(), SessionProcess.sessionOf("1 (x) S 1"));
    }
}

package phalanx.match;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

class ServerProcessTest {
    private final Path installed = Path.of("/opt/simspark/share/rcssserver3d/rcssserver3d.rb");

    @Test
    void scriptSetsSyncModeAndTheHalfAfterTheInstalledScript() {
        String s = ServerProcess.script(new ServerProcess.Settings(3500, 3600, true, true, 60, 2), installed);
        assertTrue(s.contains("$agentSyncMode = true\n"));
        assertTrue(s.contains("$serverMultiThreadedMode = false\n") && s.contains("$threadedAgentControl = false\n"));
        assertFalse(s.contains("sparkSetupTimer"), "real time keeps the server's timer");
        int run = s.indexOf("run \"/opt/simspark/share/rcssserver3d/rcssserver3d.rb\"");
        assertTrue(run > s.indexOf("$agentSyncMode"), "globals before the installed script reads them");
        assertTrue(s.indexOf("createVariable('Soccer', 'RuleHalfTime', 60.0)") > run, "soccer variables after it defines them");
        assertTrue(s.contains("'SingleHalfTime', false"));
    }

    @Test
    void fastModeDropsTheTimerAndOneHalfEndsTheGame() {
        String s = ServerProcess.script(new ServerProcess.Settings(3500, 3600, true, false, 30, 1), installed);
        assertTrue(s.contains("def sparkSetupTimer()\nend\n"));
        assertTrue(s.contains("'SingleHalfTime', true"));
    }

    @Test
    void badSettingsAreRefused() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new ServerProcess.Settings(3500, 3600, false, false, 60, 2))
                .getMessage().contains("agent-sync"));
        assertThrows(IllegalArgumentException.class, () -> new ServerProcess.Settings(3500, 3600, false, true, 60, 3));
        assertThrows(IllegalArgumentException.class, () -> new ServerProcess.Settings(3500, 3600, false, true, 0, 2));
    }

    @Test
    void optionsGiveSpecificMessages() {
        java.util.Set<String> v = MatchOptions.VALUED;
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> new Args(new String[] {"--half-time", "abc"}, v, MatchOptions.FLAGS, "match").number("half-time", 300, 1, 3600))
                .getMessage().contains("--half-time must be a number from 1 to 3600, got 'abc'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Args(new String[] {"--bogus"}, v, MatchOptions.FLAGS, "match"))
                .getMessage().contains("unknown option --bogus"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Args(new String[] {"--halves"}, v, MatchOptions.FLAGS, "match"))
                .getMessage().contains("--halves needs a value"));
    }
}

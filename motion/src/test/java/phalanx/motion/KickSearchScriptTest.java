package phalanx.motion;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.motion.phase.PhaseMotion;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * scripts/kick-search without a server: the committed strong kicks are generator 3's output for the
 * parameters `params` reads back from them (so a search can restart from a committed file), and a bad
 * score setting in the environment is refused by name. Needs python3; skips with a message without it.
 */
class KickSearchScriptTest {
    private record Run(int status, String out, String err) {}

    private static Run run(Map<String, String> env, String... args) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(args);
        pb.environment().putAll(env);
        Process p;
        try {
            p = pb.start();
        } catch (java.io.IOException e) {
            assumeTrue(false, "python3 is not installed: scripts/kick-search not tested");
            return null;
        }
        p.getOutputStream().close();
        byte[] out = p.getInputStream().readAllBytes(), err = p.getErrorStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
    }

    @Test
    void theCommittedStrongKicksAreGeneratedFromTheirOwnParameters(@TempDir Path tmp) throws Exception {
        for (String file : new String[] {"strong_kick.xml", "type4/strong_kick.xml"}) {
            Run params = run(Map.of(), "python3", "scripts/kick-search", "params", "motions/" + file);
            assertEquals(0, params.status(), params.err());
            Path json = tmp.resolve("p.json");
            Files.writeString(json, params.out());
            Run gen = run(Map.of(), "python3", "scripts/kick-search", "gen", json.toString(), "regenerated");
            assertEquals(0, gen.status(), gen.err());
            Path dir = Files.createDirectories(tmp.resolve(file.replace('/', '_')));
            Files.writeString(dir.resolve("strong_kick.xml"), gen.out());
            PhaseMotion mine = (PhaseMotion) MotionLibrary.load(dir).get("strong_kick");
            PhaseMotion committed = (PhaseMotion) MotionLibrary.load(MotionFilesTest.DIR.resolve(file).getParent()).get("strong_kick");
            assertEquals(committed.phases().size(), mine.phases().size(), file);
            for (int i = 0; i < mine.phases().size(); i++) {
                assertEquals(committed.phase(i).name(), mine.phase(i).name(), file);
                assertEquals(committed.phase(i).durationMs(), mine.phase(i).durationMs(), file + " " + mine.phase(i).name());
                assertEquals(committed.phase(i).targets(), mine.phase(i).targets(), file + " " + mine.phase(i).name());
            }
        }
    }

    @Test
    void refusesAScoreSettingThatIsNoNumber() throws Exception {
        Run r = run(Map.of("KICK_REEVAL", "often"), "python3", "scripts/kick-search", "params", "motions/strong_kick.xml");
        assertEquals(1, r.status());
        assertTrue(r.err().contains("KICK_REEVAL must be a whole number, got 'often'"), r.err());
        assertEquals("", r.out(), "nothing printed before the refusal");
        r = run(Map.of("KICK_DIR_COST", "1,5"), "python3", "scripts/kick-search", "params", "motions/strong_kick.xml");
        assertEquals(1, r.status());
        assertTrue(r.err().contains("KICK_DIR_COST must be a number, got '1,5'"), r.err());
    }
}

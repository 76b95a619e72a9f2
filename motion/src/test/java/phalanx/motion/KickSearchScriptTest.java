package phalanx.motion;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.motion.PythonScript.Run;
import phalanx.motion.phase.PhaseMotion;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/**
 * scripts/phalanx bench kick-search (scripts/lib/tools/kick-search) without a server: the committed
 * strong kicks and the quick kick are generator 3's output for the parameters `params` reads back from them (so a search
 * can restart from a committed file), and a bad score setting in the environment is refused by name.
 * Needs python3; skips with a message without it.
 */
class KickSearchScriptTest {
    private static Run run(Map<String, String> env, String... args) throws Exception {
        return PythonScript.run(env, args);
    }

    @Test
    void theCommittedGenerator3KicksAreGeneratedFromTheirOwnParameters(@TempDir Path tmp) throws Exception {
        for (String file : new String[] {"strong_kick.xml", "type4/strong_kick.xml", "quick_kick.xml"}) {
            String name = Path.of(file).getFileName().toString().replace(".xml", "");
            Run params = run(Map.of(), "scripts/lib/tools/kick-search", "params", "motions/" + file);
            assertEquals(0, params.status(), params.err());
            Path json = tmp.resolve("p.json");
            Files.writeString(json, params.out());
            Run gen = run(Map.of(), "scripts/lib/tools/kick-search", "gen", json.toString(), "regenerated");
            assertEquals(0, gen.status(), gen.err());
            Path dir = Files.createDirectories(tmp.resolve(file.replace('/', '_')));
            Files.writeString(dir.resolve(name + ".xml"), gen.out());
            PhaseMotion mine = (PhaseMotion) MotionLibrary.load(dir).get(name);
            PhaseMotion committed = (PhaseMotion) MotionLibrary.load(MotionFilesTest.DIR.resolve(file).getParent()).get(name);
            assertEquals(committed.phases().size(), mine.phases().size(), file);
            for (int i = 0; i < mine.phases().size(); i++) {
                assertEquals(committed.phase(i).name(), mine.phase(i).name(), file);
                assertEquals(committed.phase(i).durationMs(), mine.phase(i).durationMs(), file + " " + mine.phase(i).name());
                assertEquals(committed.phase(i).targets(), mine.phase(i).targets(), file + " " + mine.phase(i).name());
            }
        }
    }

    @Test
    void aBoundOnTheWholeLengthScalesEveryPhaseDownToFit(@TempDir Path tmp) throws Exception {
        Run params = run(Map.of(), "scripts/lib/tools/kick-search", "params", "motions/strong_kick.xml");
        assertEquals(0, params.status(), params.err());
        Path json = tmp.resolve("p.json");
        Files.writeString(json, params.out());
        Run gen = run(Map.of("KICK_MAX_MS", "900"), "scripts/lib/tools/kick-search", "gen", json.toString(), "bounded");
        assertEquals(0, gen.status(), gen.err());
        Files.writeString(tmp.resolve("strong_kick.xml"), gen.out());
        PhaseMotion bounded = (PhaseMotion) MotionLibrary.load(tmp).get("strong_kick");
        PhaseMotion committed = (PhaseMotion) MotionLibrary.load(MotionFilesTest.DIR).get("strong_kick");
        int total = 0, committedTotal = 0;
        for (int i = 0; i < bounded.phases().size(); i++) {
            int d = bounded.phase(i).durationMs(), c = committed.phase(i).durationMs();
            assertTrue(d >= 20 && d <= c, bounded.phase(i).name() + ": " + d + " ms against " + c);
            assertEquals(committed.phase(i).targets(), bounded.phase(i).targets(), "only the durations change");
            total += d;
            committedTotal += c;
        }
        assertTrue(committedTotal > 900, "the committed kick is longer than the bound: " + committedTotal);
        assertTrue(total <= 900 && total >= 850, "total " + total + " ms");
        Run low = run(Map.of("KICK_MAX_MS", "100"), "scripts/lib/tools/kick-search", "gen", json.toString());
        assertEquals(1, low.status());
        assertTrue(low.err().contains("KICK_MAX_MS 100 is below 200 ms"), low.err());
    }

    @Test
    void refusesAScoreSettingThatIsNoNumber() throws Exception {
        Run r = run(Map.of("KICK_REEVAL", "often"), "scripts/lib/tools/kick-search", "params", "motions/strong_kick.xml");
        assertEquals(1, r.status());
        assertTrue(r.err().contains("KICK_REEVAL must be a whole number, got 'often'"), r.err());
        assertEquals("", r.out(), "nothing printed before the refusal");
        r = run(Map.of("KICK_DIR_COST", "1,5"), "scripts/lib/tools/kick-search", "params", "motions/strong_kick.xml");
        assertEquals(1, r.status());
        assertTrue(r.err().contains("KICK_DIR_COST must be a number, got '1,5'"), r.err());
    }
}

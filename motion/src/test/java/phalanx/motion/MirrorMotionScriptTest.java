package phalanx.motion;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.motion.PythonScript.Run;
import phalanx.motion.phase.PhaseMotion;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/**
 * scripts/phalanx mirror-motion (scripts/lib/tools/mirror-motion; motions/README.md "Mirrors"): its
 * mirror of dive_left.xml is dive_right.xml, and bad input gets a clear message and status 1. Needs
 * python3; skips with a message without it.
 */
class MirrorMotionScriptTest {
    private static Run run(String... args) throws Exception {
        return PythonScript.run(java.util.Map.of(), args);
    }

    @Test
    void mirrorsTheLeftDiveIntoTheRightOne(@TempDir Path tmp) throws Exception {
        Run r = run("scripts/lib/tools/mirror-motion", "motions/dive_left.xml");
        assertEquals(0, r.status(), r.err());
        Files.writeString(tmp.resolve("dive_right.xml"), r.out());
        PhaseMotion mine = (PhaseMotion) MotionLibrary.load(tmp).get("dive_right");
        PhaseMotion committed = (PhaseMotion) MotionLibrary.load(MotionFilesTest.DIR).get("dive_right");
        assertEquals(committed.phases().size(), mine.phases().size());
        for (int i = 0; i < mine.phases().size(); i++) {
            assertEquals(committed.phase(i).name(), mine.phase(i).name());
            assertEquals(committed.phase(i).durationMs(), mine.phase(i).durationMs());
            assertEquals(committed.phase(i).targets(), mine.phase(i).targets(), "phase " + mine.phase(i).name());
        }
    }

    @Test
    void refusesAMissingFileAndAFileThatIsNoPhaseMotion(@TempDir Path tmp) throws Exception {
        Run r = run("scripts/lib/tools/mirror-motion", tmp.resolve("nope.xml").toString());
        assertEquals(1, r.status());
        assertTrue(r.err().contains("cannot read") && r.err().contains("nope.xml"), r.err());
        Path text = tmp.resolve("turn.motion");
        Files.writeString(text, "#WEBOTS_MOTION,V1.0\nHeadYaw\n00:00:000,P1,0\n");
        r = run("scripts/lib/tools/mirror-motion", text.toString());
        assertEquals(1, r.status());
        assertTrue(r.err().contains("is not an XML phase motion"), r.err());
        assertEquals("", r.out(), "nothing half-written on stdout");
        r = run("scripts/lib/tools/mirror-motion");
        assertEquals(1, r.status());
        assertTrue(r.err().contains("mirror-motion motions/kick.xml"), "usage: " + r.err());
    }
}

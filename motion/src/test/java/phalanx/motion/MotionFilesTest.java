package phalanx.motion;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.motion.phase.PhaseMotion;
import phalanx.motion.webots.TextMotion;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The project's own motion files in motions/ load and contain what the agent asks for (issue 6). */
class MotionFilesTest {
    static final Path DIR = Path.of("motions"); // the build runs tests from the project root

    @Test
    void everyRequiredMotionIsThereAndValid() throws Exception {
        assertTrue(Files.isDirectory(DIR), "run from the project root: " + DIR.toAbsolutePath());
        MotionLibrary lib = MotionLibrary.load(DIR);
        for (String name : List.of("walk_forward", "side_step_left", "side_step_right", "turn_left", "turn_right",
                "kick", "strong_kick", "kick_left", "strong_kick_left", "quick_kick", "quick_kick_left", "stand_up_front", "stand_up_back", "dive_left", "dive_right")) {
            assertNotNull(lib.get(name), "motions/ lacks " + name);
        }
        assertInstanceOf(TextMotion.class, lib.get("turn_left"), "turns are Webots text motions (4.5.3)");
        assertInstanceOf(PhaseMotion.class, lib.get("walk_forward"));
    }

    @Test
    void cyclicMotionsCanBeFinalizedAndMirrorsAreMirrored() throws Exception {
        MotionLibrary lib = MotionLibrary.load(DIR);
        PhaseMotion walk = (PhaseMotion) lib.get("walk_forward");
        assertTrue(walk.phases().stream().anyMatch(p -> p.finalizeTo() >= 0), "walk needs a finalize exit");
        TextMotion left = (TextMotion) lib.get("turn_left"), right = (TextMotion) lib.get("turn_right");
        assertEquals(left.poseCount(), right.poseCount());
        // Mirror: the left turn's left hip yaw-pitch is the right turn's right hip yaw-pitch.
        int l = left.joints().indexOf(Joint.LLJ1), r = right.joints().indexOf(Joint.RLJ1);
        for (int p = 0; p < left.poseCount(); p++) assertEquals(left.targetDeg(p, l), right.targetDeg(p, r), 1e-3);
    }

    @Test
    void leftFootKicksAndTheRightDiveAreExactMirrors() throws Exception {
        for (int type = 0; type <= 4; type++) assertMirrored(MotionLibrary.load(DIR, type)); // typeN/ files too
    }

    private static void assertMirrored(MotionLibrary lib) {
        for (String[] pair : new String[][] {{"kick", "kick_left"}, {"strong_kick", "strong_kick_left"}, {"quick_kick", "quick_kick_left"}, {"dive_left", "dive_right"}}) {
            PhaseMotion a = (PhaseMotion) lib.get(pair[0]), b = (PhaseMotion) lib.get(pair[1]);
            String what = b.source() + " mirrors " + a.source();
            assertEquals(a.phases().size(), b.phases().size(), what);
            assertEquals(a.first(), b.first(), what);
            for (int i = 0; i < a.phases().size(); i++) {
                var p = a.phase(i);
                var q = b.phase(i);
                assertEquals(List.of(p.name(), p.durationMs(), p.next(), p.finalizeTo()), List.of(q.name(), q.durationMs(), q.next(), q.finalizeTo()), what);
                assertEquals(p.targets().size(), q.targets().size(), what + ", phase " + p.name());
                for (var t : p.targets().entrySet()) {
                    Joint j = t.getKey();
                    assertTrue(q.lists(twin(j)), what + ": " + p.name() + " lists " + twin(j));
                    assertEquals(mirrorSign(j) * t.getValue(), q.targetDeg(twin(j)), 1e-9, what + ": " + p.name() + " " + j);
                }
            }
        }
    }

    /** The left-right twin of a joint (scripts/phalanx mirror-motion's rule). */
    private static Joint twin(Joint j) {
        String n = j.perceptorName();
        char side = n.charAt(0);
        return side == 'l' || side == 'r' ? Joint.byName((side == 'l' ? "r" : "l") + n.substring(1)) : j;
    }

    /** Rolls and yaws change sign in a mirror; pitches, knees, toes and the hip yaw-pitch do not. */
    private static double mirrorSign(Joint j) {
        String n = j.perceptorName();
        return n.equals("hj1") || n.matches("[lr]lj[26]") || n.matches("[lr]aj[234]") ? -1 : 1;
    }

    @Test
    void aBadFileInTheFolderStopsTheLoadWithItsName(@org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        Files.writeString(tmp.resolve("good.motion"), "#WEBOTS_MOTION,V1.0\nHeadYaw\n00:00:000,P1,0\n");
        Files.writeString(tmp.resolve("bad.xml"), "<motion><phase name=\"A\"><effectors/><duration>-1</duration></phase></motion>");
        Files.writeString(tmp.resolve("README.md"), "ignored");
        MotionFileException e = assertThrows(MotionFileException.class, () -> MotionLibrary.load(tmp));
        assertTrue(e.getMessage().contains("bad.xml") && e.getMessage().contains("duration"), e.getMessage());
        Files.delete(tmp.resolve("bad.xml"));
        Files.writeString(tmp.resolve("good.xml"), "<motion><phase name=\"A\"><effectors/><duration>20</duration></phase></motion>");
        MotionFileException dup = assertThrows(MotionFileException.class, () -> MotionLibrary.load(tmp));
        assertTrue(dup.getMessage().contains("a second motion named 'good'"), dup.getMessage());
        assertThrows(MotionFileException.class, () -> MotionLibrary.load(tmp.resolve("nope")));
    }

    @Test
    void aTypeFolderReplacesTheMotionsOfItsNamesForThatTypeOnly(@org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        Files.writeString(tmp.resolve("a.xml"), "<motion><phase name=\"A\"><effectors/><duration>20</duration></phase></motion>");
        Files.writeString(tmp.resolve("b.xml"), "<motion><phase name=\"B\"><effectors/><duration>20</duration></phase></motion>");
        Files.createDirectory(tmp.resolve("type4"));
        Files.writeString(tmp.resolve("type4/a.xml"), "<motion><phase name=\"A\"><effectors/><duration>40</duration></phase></motion>");
        PhaseMotion a4 = (PhaseMotion) MotionLibrary.load(tmp, 4).get("a");
        assertEquals(40, a4.phase(0).durationMs());
        assertEquals(20, ((PhaseMotion) MotionLibrary.load(tmp, 4).get("b")).phase(0).durationMs(), "b has no type 4 file");
        assertEquals(20, ((PhaseMotion) MotionLibrary.load(tmp, 2).get("a")).phase(0).durationMs(), "type4/ is type 4's alone");
        assertEquals(20, ((PhaseMotion) MotionLibrary.load(tmp).get("a")).phase(0).durationMs());
        assertEquals(java.util.Set.of("a", "b"), MotionLibrary.load(tmp, 4).names());

        Files.writeString(tmp.resolve("type4/c.xml"), "<motion><phase name=\"C\"><effectors/><duration>20</duration></phase></motion>");
        MotionFileException typo = assertThrows(MotionFileException.class, () -> MotionLibrary.load(tmp, 4));
        assertTrue(typo.getMessage().contains("c.xml") && typo.getMessage().contains("replaces no motion"), typo.getMessage());
        Files.writeString(tmp.resolve("type4/c.xml"), "<motion><phase name=\"C\"><effectors/><duration>0</duration></phase></motion>");
        MotionFileException bad = assertThrows(MotionFileException.class, () -> MotionLibrary.load(tmp, 4));
        assertTrue(bad.getMessage().contains("c.xml") && bad.getMessage().contains("duration"), bad.getMessage());
        assertNotNull(MotionLibrary.load(tmp, 0).get("a"), "another type never reads type4/");
    }
}

package phalanx.motion.phase;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.comm.perception.Joint;
import phalanx.motion.MotionFileException;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

class PhaseMotionLoaderTest {
    @TempDir Path dir;

    private static final String WALK = """
            <motion first="Start">
              <phase name="Start" next="Step1">
                <effectors><llj3>20</llj3><rle3>-10.5</rle3></effectors>
                <duration>100</duration>
              </phase>
              <phase name="Step1" next="Step2" swing="left">
                <effectors><llj4>-40</llj4></effectors>
                <duration>60</duration>
              </phase>
              <phase name="Step2" next="Step1" swing="right">
                <effectors/>
                <duration>60</duration>
                <finalize>Final</finalize>
              </phase>
              <phase name="Final">
                <effectors><hj1>0</hj1></effectors>
                <duration>200</duration>
              </phase>
            </motion>
            """;

    private Path write(String name, String text) throws IOException {
        Path f = dir.resolve(name);
        Files.writeString(f, text, StandardCharsets.UTF_8);
        return f;
    }

    private MotionFileException fails(String text) throws IOException {
        Path f = write("bad.xml", text);
        return assertThrows(MotionFileException.class, () -> PhaseMotionLoader.load(f));
    }

    @Test
    void loadsPhasesTargetsLinksAndDurations() throws Exception {
        PhaseMotion m = PhaseMotionLoader.load(write("walk.xml", WALK));
        assertEquals("walk", m.name());
        assertEquals(4, m.phases().size());
        assertEquals(0, m.first());
        Phase start = m.phase(0);
        assertEquals("Start", start.name());
        assertEquals(20.0, start.targetDeg(Joint.LLJ3));
        assertEquals(-10.5, start.targetDeg(Joint.RLJ3)); // effector name rle3 means joint rlj3
        assertFalse(start.lists(Joint.HJ1));
        assertEquals(100, start.durationMs());
        assertEquals(1, start.next());
        assertEquals(-1, start.finalizeTo());
        assertEquals(Phase.Swing.LEFT, m.phase(1).swing());
        Phase step2 = m.phase(2);
        assertEquals(1, step2.next());
        assertEquals(3, step2.finalizeTo());
        assertTrue(step2.targets().isEmpty());
        assertEquals(-1, m.phase(3).next());
    }

    @Test
    void firstDefaultsToTheFirstPhaseAndCanNameAnother() throws Exception {
        PhaseMotion m = PhaseMotionLoader.load(write("m.xml", WALK.replace("<motion first=\"Start\">", "<motion first=\"Final\">")));
        assertEquals(3, m.first());
        PhaseMotion d = PhaseMotionLoader.load(write("d.xml", WALK.replace("<motion first=\"Start\">", "<motion>")));
        assertEquals(0, d.first());
    }

    @Test
    void unknownJointNamesFileLinePhaseAndField() throws Exception {
        MotionFileException e = fails(WALK.replace("<llj4>-40</llj4>", "<llj9>-40</llj9>"));
        assertTrue(e.file().endsWith("bad.xml"), e.getMessage());
        assertEquals(7, e.line(), e.getMessage());
        assertEquals("phase 'Step1'", e.part());
        assertEquals("effectors/llj9", e.field());
        assertTrue(e.getMessage().contains("bad.xml:7: phase 'Step1', field 'effectors/llj9': unknown joint 'llj9'"), e.getMessage());
    }

    @Test
    void nextNamingAMissingPhase() throws Exception {
        MotionFileException e = fails(WALK.replace("next=\"Step2\"", "next=\"Step3\""));
        assertEquals("phase 'Step1'", e.part());
        assertEquals("next", e.field());
        assertTrue(e.getMessage().contains("no phase is named 'Step3'"), e.getMessage());
    }

    @Test
    void finalizeNamingAMissingPhase() throws Exception {
        MotionFileException e = fails(WALK.replace("<finalize>Final</finalize>", "<finalize>Fnal</finalize>"));
        assertEquals("phase 'Step2'", e.part());
        assertEquals("finalize", e.field());
        assertEquals(13, e.line());
        assertTrue(e.getMessage().contains("'Fnal'"), e.getMessage());
    }

    @Test
    void noFirstPhase() throws Exception {
        MotionFileException none = fails("<motion first=\"Start\"></motion>");
        assertEquals("phase", none.field());
        assertTrue(none.getMessage().contains("no first phase"), none.getMessage());
        MotionFileException missing = fails(WALK.replace("first=\"Start\"", "first=\"Begin\""));
        assertEquals("first", missing.field());
        assertTrue(missing.getMessage().contains("no first phase: no phase is named 'Begin'"), missing.getMessage());
    }

    @Test
    void durationMustBeAPositiveWholeNumber() throws Exception {
        for (String bad : new String[] {"0", "-20", "fast", "12.5", ""}) {
            MotionFileException e = fails(WALK.replace("<duration>60</duration>\n    <finalize>", "<duration>" + bad + "</duration>\n    <finalize>"));
            assertEquals("phase 'Step2'", e.part(), bad);
            assertEquals("duration", e.field(), bad);
            assertEquals(12, e.line(), bad);
        }
        MotionFileException zero = fails(WALK.replace("<duration>100</duration>", "<duration>0</duration>"));
        assertTrue(zero.getMessage().contains("0 ms: a duration must be > 0"), zero.getMessage());
        MotionFileException missing = fails(WALK.replace("<duration>200</duration>", ""));
        assertEquals("phase 'Final'", missing.part());
        assertEquals("duration", missing.field());
    }

    @Test
    void valuesMustBeNumbersWithinTheJointRange() throws Exception {
        MotionFileException nan = fails(WALK.replace("<llj3>20</llj3>", "<llj3>twenty</llj3>"));
        assertEquals("effectors/llj3", nan.field());
        MotionFileException range = fails(WALK.replace("<llj4>-40</llj4>", "<llj4>40</llj4>"));
        assertEquals("effectors/llj4", range.field());
        assertTrue(range.getMessage().contains("outside the joint's range [-130.0, 1.0]"), range.getMessage());
        MotionFileException twice = fails(WALK.replace("<llj3>20</llj3>", "<llj3>20</llj3><lle3>10</lle3>"));
        assertTrue(twice.getMessage().contains("llj3 listed twice"), twice.getMessage());
    }

    @Test
    void duplicatePhasesUnknownFieldsAndMissingParts() throws Exception {
        MotionFileException dup = fails(WALK.replace("name=\"Step2\"", "name=\"Step1\""));
        assertEquals("name", dup.field());
        assertTrue(dup.getMessage().contains("a second phase with this name"), dup.getMessage());
        MotionFileException field = fails(WALK.replace("<duration>100</duration>", "<duration>100</duration><speed>2</speed>"));
        assertEquals("speed", field.field());
        assertEquals("phase 'Start'", field.part());
        MotionFileException noEff = fails(WALK.replace("<effectors><hj1>0</hj1></effectors>", ""));
        assertEquals("effectors", noEff.field());
        MotionFileException noName = fails(WALK.replace("<phase name=\"Final\">", "<phase>"));
        assertEquals("name", noName.field());
        assertEquals("phase #4", noName.part());
        MotionFileException swing = fails(WALK.replace("swing=\"left\"", "swing=\"up\""));
        assertEquals("swing", swing.field());
    }

    @Test
    void aLoopWithoutFinalizeCannotBeStopped() throws Exception {
        MotionFileException e = fails(WALK.replace("<finalize>Final</finalize>", ""));
        assertEquals("finalize", e.field());
        assertTrue(e.getMessage().contains("Step1 -> Step2 -> Step1"), e.getMessage());
    }

    @Test
    void malformedXmlAndEmptyFiles() throws Exception {
        MotionFileException broken = fails("<motion>\n<phase name=\"A\">\n</motion>");
        assertTrue(broken.getMessage().contains("not well-formed XML"), broken.getMessage());
        assertEquals(3, broken.line());
        MotionFileException empty = fails("");
        assertTrue(empty.getMessage().startsWith(dir.resolve("bad.xml").toString()), empty.getMessage());
        MotionFileException text = fails("<motion>hello</motion>");
        assertTrue(text.getMessage().contains("unexpected text 'hello'"), text.getMessage());
    }

    @Test
    void missingFileIsReportedNotThrownRaw() {
        MotionFileException e = assertThrows(MotionFileException.class, () -> PhaseMotionLoader.load(dir.resolve("nope.xml")));
        assertTrue(e.getMessage().contains("nope.xml") && e.getMessage().contains("cannot read"), e.getMessage());
    }
}

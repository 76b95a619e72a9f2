package phalanx.motion.phase;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.motion.MotionFileException;
import phalanx.motion.MotionLibrary;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/** The phases' torso checks (closed-loop get-ups): what the loader accepts and each refusal's message. */
class CheckLoaderTest {
    @TempDir Path dir;

    private static final String UP = """
            <motion>
              <phase name="Flat" next="Rise">
                <effectors><llj3>0</llj3></effectors>
                <duration>100</duration>
                CHECK
              </phase>
              <phase name="Rise"><effectors><llj3>20</llj3></effectors><duration>100</duration></phase>
            </motion>
            """;

    private Path write(String name, String check) throws IOException {
        Path f = dir.resolve(name);
        Files.writeString(f, UP.replace("CHECK", check), StandardCharsets.UTF_8);
        return f;
    }

    private MotionFileException fails(String check) throws IOException {
        Path f = write("bad.xml", check);
        return assertThrows(MotionFileException.class, () -> PhaseMotionLoader.load(f));
    }

    @Test
    void loadsAxisRangeAndElsePhaseOrSwitch() throws Exception {
        PhaseMotion m = PhaseMotionLoader.load(write("up.xml", "<check axis=\"forward\" max=\"0.5\" else=\"Flat\"/>"));
        Check c = m.phase(0).check();
        assertEquals(Check.Axis.FORWARD, c.axis());
        assertEquals(-1.0, c.min(), "min defaults to -1");
        assertEquals(0.5, c.max());
        assertEquals(0, c.elsePhase());
        assertNull(c.switchTo());
        assertEquals(5, c.line());
        assertNull(m.phase(1).check());
        Check s = PhaseMotionLoader.load(write("up2.xml", "<check axis=\"UP\" min=\"0.2\" switch=\"other\"/>")).phase(0).check();
        assertEquals(Check.Axis.UP, s.axis());
        assertEquals(0.2, s.min());
        assertEquals(1.0, s.max(), "max defaults to 1");
        assertEquals(-1, s.elsePhase());
        assertEquals("other", s.switchTo());
    }

    @Test
    void everyBadCheckNamesFileLinePhaseAndField() throws Exception {
        MotionFileException axis = fails("<check axis=\"sideways\" max=\"0.5\" else=\"Flat\"/>");
        assertEquals("check/axis", axis.field());
        assertEquals("phase 'Flat'", axis.part());
        assertEquals(5, axis.line());
        assertTrue(axis.getMessage().startsWith(dir.resolve("bad.xml") + ":5: phase 'Flat', field 'check/axis': 'sideways' is not right, forward or up"), axis.getMessage());
        assertEquals("check/axis", fails("<check max=\"0.5\" else=\"Flat\"/>").field());
        MotionFileException range = fails("<check axis=\"up\" min=\"1.5\" else=\"Flat\"/>");
        assertEquals("check/min", range.field());
        assertTrue(range.getMessage().contains("outside [-1, 1]"), range.getMessage());
        assertEquals("check/max", fails("<check axis=\"up\" max=\"half\" else=\"Flat\"/>").field());
        MotionFileException order = fails("<check axis=\"up\" min=\"0.5\" max=\"0.2\" else=\"Flat\"/>");
        assertTrue(order.getMessage().contains("min 0.5 is above max 0.2"), order.getMessage());
        MotionFileException open = fails("<check axis=\"up\" else=\"Flat\"/>");
        assertTrue(open.getMessage().contains("always passes"), open.getMessage());
        MotionFileException both = fails("<check axis=\"up\" min=\"0\" else=\"Flat\" switch=\"x\"/>");
        assertTrue(both.getMessage().contains("exactly one of else"), both.getMessage());
        MotionFileException neither = fails("<check axis=\"up\" min=\"0\"/>");
        assertTrue(neither.getMessage().contains("exactly one of else"), neither.getMessage());
        MotionFileException noPhase = fails("<check axis=\"up\" min=\"0\" else=\"Nowhere\"/>");
        assertEquals("else", noPhase.field());
        assertTrue(noPhase.getMessage().contains("no phase is named 'Nowhere'"), noPhase.getMessage());
        assertEquals("check/speed", fails("<check axis=\"up\" min=\"0\" else=\"Flat\" speed=\"2\"/>").field());
        assertEquals("check", fails("<check/>").field());
        assertEquals("check", fails("<check axis=\"up\" min=\"0\" else=\"Flat\"/><check axis=\"up\" min=\"0\" else=\"Flat\"/>").field());
    }

    @Test
    void aSwitchMustNameAnotherMotionOfTheFolder() throws Exception {
        write("up.xml", "<check axis=\"up\" min=\"0\" switch=\"down\"/>");
        MotionFileException missing = assertThrows(MotionFileException.class, () -> MotionLibrary.load(dir));
        assertEquals("check/switch", missing.field());
        assertEquals(5, missing.line());
        assertTrue(missing.getMessage().contains("'down' is not another motion of this folder"), missing.getMessage());
        write("up.xml", "<check axis=\"up\" min=\"0\" switch=\"up\"/>");
        assertThrows(MotionFileException.class, () -> MotionLibrary.load(dir), "a switch to itself");
        write("down.xml", "");
        Files.writeString(dir.resolve("down.xml"), UP.replace("CHECK", ""), StandardCharsets.UTF_8);
        write("up.xml", "<check axis=\"up\" min=\"0\" switch=\"down\"/>");
        assertEquals("down", ((PhaseMotion) MotionLibrary.load(dir).get("up")).phase(0).check().switchTo());
    }
}

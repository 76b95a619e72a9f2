package phalanx.bench.coordination;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.ReportType;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

class ScenarioFileTest {
    private static String message(String text) {
        return assertThrows(ScenarioFile.ScenarioException.class, () -> ScenarioFile.parse(text, "t.txt")).getMessage();
    }

    @Test
    void readsEveryDirective() throws Exception {
        Scenario s = ScenarioFile.parse("""
                # a comment
                field 9
                mode support     # trailing comment
                mapper scram
                previous 4 1.5 -2
                ball 1 1
                C 2 -3 1 45 1 -1
                L 3 0 0 0 fallen
                B 4 2.5 -30 90
                B 5 1 10 fallen
                X 6
                """, "t.txt");
        assertEquals(FieldSpec.V065, s.beliefs().field());
        assertEquals(Mode.SUPPORT, s.mode());
        assertEquals("scram", s.mapper());
        assertEquals(new Memory(4, new Vector2(1.5, -2)), s.memory());
        assertEquals(new Vector2(1, 1), s.beliefs().fallbackBall());
        assertEquals(5, s.beliefs().reports().size());
        PlayerReport c = s.beliefs().reports().get(0);
        assertEquals(ReportType.C, c.type());
        assertEquals(45, c.self().thetaDeg());
        assertEquals(new Vector2(1, -1), c.ball());
        assertTrue(s.beliefs().reports().get(1).fallen());
        assertEquals(90, s.beliefs().reports().get(2).headingDeg());
        assertTrue(Double.isNaN(s.beliefs().reports().get(3).headingDeg()));
        assertTrue(s.beliefs().reports().get(3).fallen());
        assertEquals(ReportType.X, s.beliefs().reports().get(4).type());
    }

    @Test
    void badLinesAreNamedByFileAndLine() {
        assertEquals("t.txt:2: unknown directive 'Q' (field, mode, mapper, previous, ball, C, L, B, X)", message("X 2\nQ 1 2\n"));
        assertEquals("t.txt:1: field must be 9 or 11 players, got 10", message("field 10\nX 2"));
        assertEquals("t.txt:1: value 1 of field is not a whole number: 'eleven'", message("field eleven\nX 2"));
        assertEquals("t.txt:1: mode must be active, support or wait, got 'attack'", message("mode attack\nX 2"));
        assertEquals("t.txt:1: mapper must be dp or scram, got 'greedy'", message("mapper greedy\nX 2"));
        assertEquals("t.txt:1: value 3 of C is not a number: 'x'", message("C 2 1 x 0 0 0"));
        assertEquals("t.txt:1: value 2 of L is not finite: 'NaN'", message("L 2 NaN 0 0"));
        assertEquals("t.txt:1: C takes 6 values and an optional 'fallen', got: C 2 1 1 0 0", message("C 2 1 1 0 0"));
        assertEquals("t.txt:1: B takes: id distance bearing [heading] [fallen]", message("B 2 1"));
        assertEquals("t.txt:1: previous takes an id, or an id and the ball's x and y", message("previous 3 1\nX 2"));
        assertEquals("t.txt:1: ball takes 2 values, got 1", message("ball 3\nX 2"));
        assertEquals("t.txt: no player report (C, L, B or X lines)", message("field 11\n"));
    }

    @Test
    void shippedScenariosParse() throws Exception {
        Path dir = Path.of("bench/scenarios");
        for (String name : new String[]{"offense.txt", "defense.txt"}) {
            Scenario s = ScenarioFile.parse(Files.readString(dir.resolve(name)), name);
            assertEquals(11, s.beliefs().reports().size(), name);
        }
    }
}

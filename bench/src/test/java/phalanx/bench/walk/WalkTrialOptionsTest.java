package phalanx.bench.walk;

import phalanx.motion.walk.WalkConfig;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class WalkTrialOptionsTest {
    private static String error(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> WalkTrialOptions.parse(args).config()).getMessage();
    }

    @Test
    void defaults() {
        WalkTrialOptions o = WalkTrialOptions.parse();
        assertEquals(3100, o.port());
        assertEquals(3200, o.monitorPort());
        assertEquals(List.of(0, 2, 4), o.types());
        assertEquals(WalkTrialOptions.DEFAULT_SCENARIOS, o.scenarios());
        assertEquals(1, o.seed());
        assertEquals(60, o.mixedSeconds());
        assertEquals(WalkConfig.DEFAULT, o.config());
    }

    @Test
    void flagsAreRead() {
        WalkTrialOptions o = WalkTrialOptions.parse("--port", "3910", "--monitor-port", "3920", "--type", "1,3",
                "--scenarios", "turn,forward10", "--set", "stepSeconds=0.2,maxForward=0.5", "--search", "stepHeight:0.01", "--rounds", "2", "--starts", "3");
        assertEquals(3910, o.port());
        assertEquals(List.of(1, 3), o.types());
        assertEquals(List.of("turn", "forward10"), o.scenarios());
        assertEquals(0.2, o.config().stepSeconds());
        assertEquals(0.5, o.config().maxForward());
        assertEquals(0.01, o.search().get("stepHeight"));
        assertEquals(2, o.rounds());
        assertEquals(3, o.starts());
        WalkTrialOptions m = WalkTrialOptions.parse("--scenarios", "mixed", "--seed", "7", "--mixed-seconds", "30");
        assertEquals(List.of("mixed"), m.scenarios());
        assertEquals(7, m.seed());
        assertEquals(30, m.mixedSeconds());
        assertTrue(WalkTrialOptions.parse("--score", "--type", "2").score());
        assertFalse(m.score());
    }

    @Test
    void everyBadFlagIsNamed() {
        assertTrue(error("--port").contains("--port needs a value"));
        assertTrue(error("--port", "x").contains("--port needs a whole number, got 'x'"));
        assertTrue(error("--port", "70000").contains("--port must be in"));
        assertTrue(error("--type", "0,0").contains("--type lists 0 twice"));
        assertTrue(error("--type", "5").contains("--type must be in"));
        assertTrue(error("--scenarios", "run").contains("unknown scenario 'run'"));
        assertTrue(error("--set", "speed=1").contains("no field 'speed'"));
        assertTrue(error("--set", "stepSeconds").contains("needs field=number pairs"));
        assertTrue(error("--set", "stepSeconds=fast").contains("needs a number, got 'fast'"));
        assertTrue(error("--set", "stepSeconds=5").contains("stepSeconds must be in"));
        assertTrue(error("--search", "stepSeconds:-1").contains("--search stepSeconds must be in"));
        assertTrue(error("--bogus", "1").contains("unknown flag '--bogus'"));
        assertTrue(error("--starts", "0").contains("--starts must be in"));
        assertTrue(error("--seed", "-1").contains("--seed must be in"));
        assertTrue(error("--seed", "one").contains("--seed needs a whole number, got 'one'"));
        assertTrue(error("--mixed-seconds", "0").contains("--mixed-seconds must be in"));
        assertTrue(error("--score", "--type", "0", "--search", "stepHeight:0.01").contains("--score and --search exclude each other"));
        assertTrue(error("--score").contains("--score scores one robot type: give --type with one type, got [0, 2, 4]"));
        assertTrue(error("--help").startsWith("usage: scripts/phalanx bench walk"));
    }
}

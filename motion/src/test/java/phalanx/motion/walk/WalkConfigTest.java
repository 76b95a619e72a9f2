package phalanx.motion.walk;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class WalkConfigTest {
    @Test
    void withChangesOneFieldAndKeepsTheRest() {
        WalkConfig c = WalkConfig.DEFAULT.with("stepSeconds", 0.2);
        assertEquals(0.2, c.stepSeconds());
        for (String f : WalkConfig.FIELDS) if (!f.equals("stepSeconds")) assertEquals(WalkConfig.DEFAULT.get(f), c.get(f), f);
    }

    @Test
    void badFieldsAndValuesAreNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> WalkConfig.DEFAULT.with("stepLength", 1));
        assertTrue(e.getMessage().contains("no field 'stepLength'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> WalkConfig.DEFAULT.with("doubleSupport", 0.9));
        assertTrue(e.getMessage().contains("doubleSupport must be in [0.0, 0.8], got 0.9"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> WalkConfig.DEFAULT.with("stepHeight", Double.NaN));
        assertTrue(e.getMessage().contains("stepHeight"), e.getMessage());
    }

    @Test
    void everyFieldHasTheRangeTheConstructorChecks() {
        assertArrayEquals(new double[] {0, 0.8}, WalkConfig.range("doubleSupport"));
        for (String f : WalkConfig.FIELDS) {
            double[] r = WalkConfig.range(f);
            assertTrue(r[0] <= WalkConfig.DEFAULT.get(f) && WalkConfig.DEFAULT.get(f) <= r[1], f);
            WalkConfig.DEFAULT.with(f, r[0]);   // both ends are allowed
            WalkConfig.DEFAULT.with(f, r[1]);
            assertThrows(IllegalArgumentException.class, () -> WalkConfig.DEFAULT.with(f, r[1] + 1e-6), f);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> WalkConfig.range("stepLength"));
        assertTrue(e.getMessage().contains("no field 'stepLength'"), e.getMessage());
    }

    @Test
    void describeListsEveryField() {
        String d = WalkConfig.DEFAULT.describe();
        for (String f : WalkConfig.FIELDS) assertTrue(d.contains(f + "="), f);
    }

    @Test
    void perTypeConfigs() {
        assertSame(WalkConfig.DEFAULT, WalkConfig.forType(0));
        assertSame(WalkConfig.DEFAULT, WalkConfig.forType(4));
        assertSame(WalkConfig.DEFAULT, WalkConfig.forType(2));
        for (int t = 0; t <= 4; t++) assertNotNull(WalkConfig.forType(t));
        assertThrows(IllegalArgumentException.class, () -> WalkConfig.forType(5));
    }
}

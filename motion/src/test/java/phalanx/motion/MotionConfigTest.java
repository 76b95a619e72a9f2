package phalanx.motion;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class MotionConfigTest {
    @Test
    void standTimesOutsideZeroToFiveSecondsAreRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MotionConfig.DEFAULT.withStand(-0.1, 0));
        assertEquals("standBeforeSeconds must be 0-5, got -0.1", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> MotionConfig.DEFAULT.withStand(0, Double.NaN));
        assertEquals("standAfterSeconds must be 0-5, got NaN", e.getMessage());
        // whole cycles of 0.02 s
        assertEquals(25, MotionConfig.DEFAULT.withStand(0.5, 0.31).standBeforeCycles());
        assertEquals(16, MotionConfig.DEFAULT.withStand(0.5, 0.31).standAfterCycles());
    }
}

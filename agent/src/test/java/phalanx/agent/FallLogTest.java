package phalanx.agent;

import org.junit.jupiter.api.Test;
import phalanx.localization.fall.FallState;

import static org.junit.jupiter.api.Assertions.*;

class FallLogTest {
    @Test
    void oneLineDownAndOneUpWithTheTimeLying() {
        FallLog log = new FallLog();
        assertNull(log.update(FallState.STANDING, 10));
        assertNull(log.update(FallState.FALLING, 10.02));
        assertEquals("fall 1: FALLEN_BACK at game time 10.50", log.update(FallState.FALLEN_BACK, 10.5));
        assertNull(log.update(FallState.FALLEN_FRONT, 11), "still down: the same fall");
        assertNull(log.update(FallState.FALLING, 12), "rising: not standing yet");
        assertNull(log.update(FallState.STANDING, 12.2), "upright halfway through the get-up ...");
        assertNull(log.update(FallState.FALLEN_FRONT, 12.6), "... and back down: the same fall");
        assertNull(log.update(FallState.STANDING, 12.75));
        assertNull(log.update(FallState.STANDING, 13.5), "not yet a second upright");
        assertEquals("fall 1: standing again at game time 12.75 after 2.25 s", log.update(FallState.STANDING, 13.75));
        assertNull(log.update(FallState.STANDING, 14));
        assertEquals("fall 2: FALLEN_FRONT at game time 20.00", log.update(FallState.FALLEN_FRONT, 20));
        assertEquals(2, log.falls());
        assertNull(log.update(null, 21));
    }
}

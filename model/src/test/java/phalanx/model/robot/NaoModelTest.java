package phalanx.model.robot;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class NaoModelTest {

    /** The recordings README gives the standing torso heights: 0.3839 (types 0, 2, 4), 0.4205 (1), 0.4396 (3). */
    @Test
    void standingHeightsMatchTheRecordedTorsoHeights() {
        for (int t : new int[] {0, 2, 4}) assertEquals(0.3839, NaoModel.ofType(t).standingTorsoHeight(), 0.003);
        assertEquals(0.4205, NaoModel.ofType(1).standingTorsoHeight(), 0.003);
        assertEquals(0.4396, NaoModel.ofType(3).standingTorsoHeight(), 0.003);
    }

    @Test
    void refusesAnUnknownType() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> NaoModel.ofType(5));
        assertTrue(e.getMessage().contains("0-4"));
    }
}

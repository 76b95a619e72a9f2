package phalanx.localization.body;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

import static org.junit.jupiter.api.Assertions.*;

class NaoBodyTest {

    /** The recordings README gives the standing torso heights: 0.3839 (types 0, 2, 4), 0.4205 (1), 0.4396 (3). */
    @Test
    void standingHeightsMatchTheRecordedTorsoHeights() {
        assertEquals(0.3839, NaoBody.ofType(0).standingTorsoHeight(), 0.003);
        assertEquals(0.3839, NaoBody.ofType(2).standingTorsoHeight(), 0.003);
        assertEquals(0.3839, NaoBody.ofType(4).standingTorsoHeight(), 0.003);
        assertEquals(0.4205, NaoBody.ofType(1).standingTorsoHeight(), 0.003);
        assertEquals(0.4396, NaoBody.ofType(3).standingTorsoHeight(), 0.003);
    }

    @Test
    void bentKneesLowerTheTorsoByTheCosines() {
        double[] d = new double[Joint.COUNT];
        d[Joint.LLJ3.ordinal()] = 30; d[Joint.LLJ4.ordinal()] = -60; d[Joint.LLJ5.ordinal()] = 30;
        double[] sole = NaoBody.ofType(0).soleInTorso(new JointAngles(d), true);
        // 0.115 + 0.12 cos 30 + 0.10 cos(-30) + 0.05 cos 0 = 0.35553
        assertEquals(-0.35553, sole[1], 1e-4);
        // forward: 0.12 sin 30 + 0.10 sin(-30) = 0.01
        assertEquals(0.01, sole[0], 1e-9);
    }

    @Test
    void unknownTypeIsRefusedWithItsNumber() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> NaoBody.ofType(7));
        assertTrue(e.getMessage().contains("7"));
    }
}

package phalanx.model.robot;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

import static org.junit.jupiter.api.Assertions.*;

class SoleInTorsoTest {

    @Test
    void bentKneesLowerTheTorsoByTheCosines() {
        double[] d = new double[Joint.COUNT];
        d[Joint.LLJ3.ordinal()] = 30; d[Joint.LLJ4.ordinal()] = -60; d[Joint.LLJ5.ordinal()] = 30;
        double[] sole = NaoModel.ofType(0).soleInTorso(new JointAngles(d), true);
        // 0.115 + 0.12 cos 30 + 0.10 cos(-30) + 0.05 cos 0 = 0.35553
        assertEquals(-0.35553, sole[1], 1e-4);
        // forward: 0.12 sin 30 + 0.10 sin(-30) = 0.01
        assertEquals(0.01, sole[0], 1e-9);
    }
}

package phalanx.bench.motion;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class BenchRigTest {
    @Test
    void aPictureIsCurrentWithinTwoCyclesOfThePlayersGameTime() {
        assertTrue(BenchRig.current(1.02, 1.00), "the monitor sees the cycle after it was stepped");
        assertTrue(BenchRig.current(0.98, 1.00), "a picture every other cycle ($monitorStep = 0.04)");
        assertTrue(BenchRig.current(1.000, 1.00));
        assertFalse(BenchRig.current(0.50, 1.00), "seconds behind: the reader fell behind the server");
        assertFalse(BenchRig.current(301.4, 0.06), "from before the trainer's (time 0)");
        assertFalse(BenchRig.current(Double.NaN, 1.00), "a picture without a time");
    }
}

package phalanx.bench.mj;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The T1 bench's get-up options, refused before any server starts; its reading of how a robot lies. */
class T1BenchOptionsTest {
    @Test
    void aBadLyingOrSeedIsRefusedWithWhatIsAllowed() {
        IllegalArgumentException lying = assertThrows(IllegalArgumentException.class,
                () -> T1Bench.main(new String[]{"--trial", "getup", "--lying", "front,sideways"}));
        assertTrue(lying.getMessage().contains("--lying front|back|both|fall-front|fall-back"), lying.getMessage());
        assertThrows(NumberFormatException.class, () -> T1Bench.main(new String[]{"--trial", "getup", "--seed", "x"}));
    }

    @Test
    void readsFaceDownFaceUpAndSides() {
        double s = Math.sqrt(0.5);
        assertEquals("front", T1Bench.lyingOn(new double[]{s, 0, s, 0}), "pitched +90 deg about y: x axis down");
        assertEquals("back", T1Bench.lyingOn(new double[]{s, 0, -s, 0}));
        assertEquals("right side", T1Bench.lyingOn(new double[]{s, s, 0, 0}), "rolled +90 deg about x: left axis up");
        assertEquals("left side", T1Bench.lyingOn(new double[]{s, -s, 0, 0}));
    }
}

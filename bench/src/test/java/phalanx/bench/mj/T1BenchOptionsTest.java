package phalanx.bench.mj;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The T1 bench's options, bad ones refused before any server starts; its reading of how a robot lies; its yaw steps. */
class T1BenchOptionsTest {
    @Test
    void aBadLyingOrSeedIsRefusedWithWhatIsAllowed() {
        IllegalArgumentException lying = assertThrows(IllegalArgumentException.class,
                () -> T1Bench.run(new String[]{"--trial", "getup", "--lying", "front,sideways"}));
        assertTrue(lying.getMessage().contains("--lying front|back|both|fall-front|fall-back"), lying.getMessage());
        IllegalArgumentException seed = assertThrows(IllegalArgumentException.class, () -> T1Bench.run(new String[]{"--trial", "getup", "--seed", "x"}));
        assertEquals("--seed needs a number, got 'x'", seed.getMessage());
    }

    @Test
    void theGetUpOptionsAreRefusedByNameAndAMissingValueToo() {
        for (String[] bad : new String[][]{{"--recover", "x"}, {"--getup-set", "foo=1"}, {"--recover-set", "footX"}, {"--getup-set", "recoverS=-1"},
                {"--getups"}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> T1Bench.run(bad), String.join(" ", bad));
            assertTrue(e.getMessage().contains(bad[0]) || e.getMessage().contains("foo") || e.getMessage().contains("recoverS"), e.getMessage());
        }
        assertEquals("--getups needs a value", assertThrows(IllegalArgumentException.class, () -> T1Bench.run(new String[]{"--getups"})).getMessage());
    }

    @Test
    void badBlendOptionsAreRefusedWithWhatIsExpected() {
        IllegalArgumentException before = assertThrows(IllegalArgumentException.class, () -> T1Bench.run(new String[]{"--walk-set", "sway=0.1"}));
        assertTrue(before.getMessage().contains("after --preset blend"), before.getMessage());
        IllegalArgumentException noValue = assertThrows(IllegalArgumentException.class,
                () -> T1Bench.run(new String[]{"--preset", "blend", "--turn-set", "sway"}));
        assertTrue(noValue.getMessage().contains("--turn-set FIELD=VALUE, got 'sway'"), noValue.getMessage());
        IllegalArgumentException pair = assertThrows(IllegalArgumentException.class,
                () -> T1Bench.run(new String[]{"--preset", "blend", "--turn-at-speed", "10"}));
        assertTrue(pair.getMessage().contains("--turn-at-speed DEG_S,M_S"), pair.getMessage());
        IllegalArgumentException phase = assertThrows(IllegalArgumentException.class,
                () -> T1Bench.run(new String[]{"--trial", "walkturn", "--phase", "0"}));
        assertTrue(phase.getMessage().contains("--phase S must be at least one cycle"), phase.getMessage());
    }

    @Test
    void aYawStepGoesTheShortWayRound() {
        assertEquals(Math.toRadians(20), T1Bench.yawStep(Math.toRadians(170), Math.toRadians(-170)), 1e-12);
        assertEquals(Math.toRadians(-20), T1Bench.yawStep(Math.toRadians(-170), Math.toRadians(170)), 1e-12);
        assertEquals(0.1, T1Bench.yawStep(0.2, 0.3), 1e-12);
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

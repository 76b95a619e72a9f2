package phalanx.bench.motion;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class BenchOptionsTest {
    @Test
    void defaultsAndFlags() {
        BenchOptions d = BenchOptions.parse();
        assertEquals("127.0.0.1", d.host());
        assertEquals(3100, d.port());
        assertEquals(3200, d.monitorPort());
        assertEquals(List.of(0, 1, 2), d.types());
        BenchOptions o = BenchOptions.parse("--host", "h", "--port", "3310", "--monitor-port", "3410", "--type", "4, 3", "--trials", "5", "--only", "kick");
        assertEquals(3310, o.port());
        assertEquals(3410, o.monitorPort());
        assertEquals(List.of(4, 3), o.types());
        assertTrue(o.runs("kick"));
        assertFalse(o.runs("walk"));
        assertEquals(List.of("kick", "strong_kick"), d.kicks());
        BenchOptions k = BenchOptions.parse("--only", "dive", "--kicks", "kick_left, strong_kick", "--ball-ahead", "0.2",
                "--ball-side", "-0.01", "--ball-jitter", "0.02", "--dive-offset", "0.4", "--shot-seconds", "1.2");
        assertTrue(k.runs("dive"));
        assertEquals(List.of("kick_left", "strong_kick"), k.kicks());
        assertEquals(0.2, k.ballAhead());
        assertEquals(-0.01, k.ballSide());
        assertEquals(0.02, k.ballJitter());
        assertEquals(0, d.ballJitter(), "the ball exactly on the spot unless asked");
        assertEquals(0.4, k.diveOffset());
        assertEquals(1.2, k.shotSeconds());
    }

    @Test
    void badFlagsAreNamed() {
        assertTrue(msg("--port", "abc").contains("--port needs a whole number, got 'abc'"));
        assertTrue(msg("--port", "70000").contains("--port must be in [1, 65535]"));
        assertTrue(msg("--type", "5").contains("--type must be in [0, 4], got 5"));
        assertTrue(msg("--type", "1,1").contains("--type lists 1 twice"));
        assertTrue(msg("--speed", "2").contains("unknown flag '--speed'"));
        assertTrue(msg("--host").contains("--host needs a value"));
        assertTrue(msg("--only", "dance").contains("--only must be"));
        assertTrue(msg("--kicks", ",").contains("--kicks needs at least one motion name"));
        assertTrue(msg("--ball-ahead", "1").contains("--ball-ahead must be in [0, 0.5], got 1"));
        assertTrue(msg("--ball-jitter", "0.1").contains("--ball-jitter must be in [0, 0.05], got 0.1"));
        assertTrue(msg("--shot-seconds", "x").contains("--shot-seconds needs a number, got 'x'"));
        assertTrue(msg("--lying", "front,upside-down").contains("--lying takes front, back, side, oblique, got 'upside-down'"));
        assertTrue(msg("--getup-walk", "-1").contains("--getup-walk must be in [0, 60]"));
    }

    @Test
    void getupFlags() {
        BenchOptions o = BenchOptions.parse("--lying", "back, side", "--getup-walk", "0");
        assertEquals(java.util.List.of("back", "side"), o.lying());
        assertEquals(0, o.getupWalkSeconds());
        assertEquals(java.util.List.of("front", "back", "side", "oblique"), BenchOptions.parse().lying());
    }

    private static String msg(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> BenchOptions.parse(args)).getMessage();
    }
}

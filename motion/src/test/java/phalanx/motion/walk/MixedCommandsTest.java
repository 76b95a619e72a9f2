package phalanx.motion.walk;

import org.junit.jupiter.api.Test;

import java.util.EnumSet;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class MixedCommandsTest {
    private static final WalkConfig C = WalkConfig.DEFAULT;

    @Test
    void sameSeedSameSequenceOtherSeedAnother() {
        assertEquals(MixedCommands.generate(3, 60, C), MixedCommands.generate(3, 60, C));
        assertNotEquals(MixedCommands.generate(3, 60, C), MixedCommands.generate(4, 60, C));
    }

    @Test
    void coversTheLengthAndStaysWithinBodysRequests() {
        for (long seed = 0; seed < 20; seed++) {
            List<MixedCommands.Segment> seq = MixedCommands.generate(seed, 60, C);
            double total = seq.stream().mapToDouble(MixedCommands.Segment::seconds).sum();
            assertTrue(total >= 60 && total < 60 + 6 * MixedCommands.BURST_MAX + MixedCommands.MAX_SECONDS, "seed " + seed + ": " + total + " s");
            for (MixedCommands.Segment s : seq) {
                WalkVelocity v = s.request();
                boolean burst = s.kind() == MixedCommands.Kind.STEER_WALK || s.kind() == MixedCommands.Kind.STEER_TURN;
                double lo = burst ? MixedCommands.BURST_MIN : MixedCommands.MIN_SECONDS, hi = burst ? MixedCommands.BURST_MAX : MixedCommands.MAX_SECONDS;
                assertTrue(s.seconds() >= lo && s.seconds() <= hi, s.toString());
                assertTrue(v.forward() <= C.maxForward() && v.forward() >= -0.5 * C.maxBackward(), s.toString());
                assertTrue(Math.abs(v.left()) <= C.maxLeft(), s.toString());
                assertTrue(Math.abs(v.turnDeg()) <= C.maxTurnDeg(), s.toString());
                switch (s.kind()) {
                    case FORWARD, STEER_WALK -> {   // full speed, lean = at most half the turn limit
                        assertEquals(C.maxForward(), v.forward());
                        assertTrue(Math.abs(v.turnDeg()) <= 0.5 * C.maxTurnDeg(), s.toString());
                    }
                    case SLOW -> assertEquals(0.4 * C.maxForward(), v.forward(), 1e-12);
                    case TURN, STEER_TURN -> {      // in place, 30..90 deg/s at the default limit
                        assertEquals(0, v.forward());
                        assertTrue(Math.abs(v.turnDeg()) >= 0.3 * C.maxTurnDeg() - 1e-9, s.toString());
                    }
                    case SIDE -> assertEquals(C.maxLeft(), Math.abs(v.left()));
                    case BACK -> assertEquals(-0.5 * C.maxBackward(), v.forward());
                    case STOP -> assertTrue(v.isZero());
                }
            }
        }
    }

    @Test
    void aMinuteHasEveryKindAndBurstsAlternateOneWay() {
        EnumSet<MixedCommands.Kind> seen = EnumSet.noneOf(MixedCommands.Kind.class);
        List<MixedCommands.Segment> seq = MixedCommands.generate(1, 600, C);
        for (int i = 0; i < seq.size(); i++) {
            MixedCommands.Segment s = seq.get(i);
            seen.add(s.kind());
            if (s.kind() == MixedCommands.Kind.STEER_TURN) {   // Steer turns the way it leaned, walk <-> turn
                MixedCommands.Segment walk = seq.get(i - 1);
                assertEquals(MixedCommands.Kind.STEER_WALK, walk.kind());
                assertEquals(Math.signum(walk.request().turnDeg()), Math.signum(s.request().turnDeg()));
            }
        }
        assertEquals(EnumSet.allOf(MixedCommands.Kind.class), seen);
    }

    @Test
    void badLengthIsRefused() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> MixedCommands.generate(1, 0, C)).getMessage().contains("positive number of seconds"));
        assertThrows(IllegalArgumentException.class, () -> MixedCommands.generate(1, Double.NaN, C));
    }
}

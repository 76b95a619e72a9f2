package phalanx.agent.goalkeeper;

import org.junit.jupiter.api.Test;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

class BallRollTest {

    @Test
    void crossingWithRollingFrictionByHand() {
        // Ball 2 m ahead, 0.5 m left, rolling at (-3, -0.3) m/s, k = 1.05 /s:
        // e^(-k t) = 1 - k x / |vx| = 1 - 1.05 * 2 / 3 = 0.3, t = -ln(0.3) / 1.05 = 1.1466 s;
        // the path is straight: y = 0.5 - 0.3 * 2 / 3 = 0.3 m.
        BallRoll.Crossing c = BallRoll.crossing(new Vector2(2, 0.5), new Vector2(-3, -0.3), 1.05);
        assertEquals(1.14664, c.seconds(), 1e-5);
        assertEquals(0.3, c.lateral(), 1e-12);
        // Without friction the same ball takes 2 / 3 s.
        assertEquals(2.0 / 3, BallRoll.crossing(new Vector2(2, 0.5), new Vector2(-3, -0.3), 0).seconds(), 1e-12);
    }

    @Test
    void aBallThatStopsShortOrMovesAwayNeverCrosses() {
        // Reach v/k = 2 / 1.05 = 1.905 m < 2 m: it stops 9.5 cm short.
        assertNull(BallRoll.crossing(new Vector2(2, 0), new Vector2(-2, 0), 1.05));
        assertNotNull(BallRoll.crossing(new Vector2(1.9, 0), new Vector2(-2, 0), 1.05));
        assertNull(BallRoll.crossing(new Vector2(2, 0), new Vector2(1, 0), 1.05), "away");
        assertNull(BallRoll.crossing(new Vector2(2, 0), new Vector2(0, 1), 1.05), "across");
        assertNull(BallRoll.crossing(new Vector2(-1, 0), new Vector2(-1, 0), 1.05), "behind");
        assertNull(BallRoll.crossing(new Vector2(Double.NaN, 0), new Vector2(-1, 0), 1.05));
        assertNull(BallRoll.crossing(new Vector2(2, 0), null, 1.05));
        assertNull(BallRoll.crossing(new Vector2(2, 0), new Vector2(-1, 0), Double.NaN));
    }

    @Test
    void distanceFollowsTheExponentialDecay() {
        assertEquals(3 * (1 - Math.exp(-1.05)) / 1.05, BallRoll.distance(3, 1.05, 1), 1e-12);
        assertEquals(3 / 1.05, BallRoll.distance(3, 1.05, 1000), 1e-9, "at most v0 / k");
        assertEquals(1.5, BallRoll.distance(3, 0, 0.5), 1e-12);
    }
}

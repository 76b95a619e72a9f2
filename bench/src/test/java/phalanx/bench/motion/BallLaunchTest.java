package phalanx.bench.motion;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class BallLaunchTest {
    @Test
    void highestSpeedsBetweenPicturesOfDifferentTime() {
        BallLaunch l = new BallLaunch();
        l.add(1.00, 0, 0, 0.042);
        l.add(1.02, 0, 0, 0.042);            // at rest
        l.add(1.04, 0.12, 0.05, 0.082);      // 0.13 m and 4 cm up in 0.02 s: 6.5 m/s, 2 m/s up
        l.add(1.04, 9, 9, 9);                // the same picture again: ignored
        l.add(1.06, 0.22, 0.05, 0.092);      // slower
        l.add(1.08, 0.30, 0.05, 0.060);      // falling
        assertEquals(6.5, l.speed(), 1e-9);
        assertEquals(2.0, l.up(), 1e-9);
    }

    @Test
    void aBallThatNeverMovesHasNoSpeed() {
        BallLaunch l = new BallLaunch();
        for (int i = 0; i < 10; i++) l.add(i * 0.02, 1, 1, 0.042);
        assertEquals(0, l.speed());
        assertEquals(0, l.up());
    }
}

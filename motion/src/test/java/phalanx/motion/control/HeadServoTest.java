package phalanx.motion.control;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class HeadServoTest {
    @Test
    void closesTheErrorInProportionAndCapsTheSpeed() {
        // 10 deg of error: 8/s x 0.1745 rad = 1.396 rad/s toward the target
        assertEquals(8 * Math.toRadians(10), HeadServo.velocity(30, 20), 1e-12);
        assertEquals(-8 * Math.toRadians(10), HeadServo.velocity(-20, -10), 1e-12);
        // 90 deg of error would ask 12.6 rad/s: capped at 6 either way
        assertEquals(6.0, HeadServo.velocity(90, 0), 0);
        assertEquals(-6.0, HeadServo.velocity(-90, 0), 0);
        assertEquals(0.0, HeadServo.velocity(15, 15), 0);
    }
}

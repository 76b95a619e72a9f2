package phalanx.localization.body;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Vector3;

import static org.junit.jupiter.api.Assertions.*;

class TiltEstimatorTest {

    @Test
    void integratesTheGyroWhenTheAccelerometerIsUntrustworthy() {
        TiltEstimator t = new TiltEstimator(0.05, 3);
        t.update(null, new Vector3(0, 0, 9.81), 0.02);
        // 50 cycles at 30 °/s about the right axis with a free-falling accelerometer: 30° backwards.
        for (int i = 0; i < 50; i++) t.update(new Vector3(30, 0, 0), new Vector3(0, -1, 2), 0.02);
        assertEquals(30, t.tiltDeg(), 0.5);
        assertTrue(t.up().y() > 0, "leaning back: the up axis has a forward component");
    }

    @Test
    void convergesToTheAccelerometerWhenStill() {
        TiltEstimator t = new TiltEstimator(0.05, 3);
        t.update(null, new Vector3(0, 0, 9.81), 0.02);
        for (int i = 0; i < 200; i++) t.update(Vector3.ZERO, new Vector3(0, 9.81, 0), 0.02);
        assertEquals(90, t.tiltDeg(), 0.5);
    }
}

package phalanx.localization.body;

import phalanx.model.robot.NaoModel;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.Vector3;

import static org.junit.jupiter.api.Assertions.*;

class CameraPoseTest {
    private static final NaoModel BODY = NaoModel.ofType(0);

    @Test
    void uprightStraightHeadSitsThe155MillimetresAboveTheTorso() {
        CameraPose c = CameraPose.upright(BODY, 0, 0);
        Vector3 v = c.toBody(new Polar(10, 0, 0));
        assertEquals(10, v.x(), 1e-9);
        assertEquals(0, v.y(), 1e-9);
        assertEquals(0.155, v.z(), 1e-9);
        assertEquals(0.385 + 0.155, c.cameraHeight(), 1e-9);
    }

    @Test
    void headYawTurnsTheViewLeft() {
        Vector3 v = CameraPose.upright(BODY, 90, 0).toBody(new Polar(2, 0, 0));
        assertEquals(0, v.x(), 1e-9);
        assertEquals(2, v.y(), 1e-9);
        Vector3 w = CameraPose.upright(BODY, 30, 0).toBody(new Polar(3, -30, 0));
        assertEquals(3, w.x(), 1e-9);
        assertEquals(0, w.y(), 1e-9);
    }

    @Test
    void positiveHeadPitchLiftsTheView() {
        Vector3 v = CameraPose.upright(BODY, 0, 30).toBody(new Polar(2, 0, 0));
        assertEquals(2 * Math.cos(Math.toRadians(30)), v.x(), 0.01);
        assertTrue(v.z() > 0.155 + 0.9, "looking up 30°, 2 m ahead lies 1 m higher: " + v);
    }

    @Test
    void torsoLeaningForwardTurnsTheViewDown() {
        double a = Math.toRadians(20);
        // Leaning forward by 20°: the accelerometer's up has a backward (-y) component in the torso frame.
        Vector3 acc = new Vector3(0, -9.81 * Math.sin(a), 9.81 * Math.cos(a));
        double[] d = new double[Joint.COUNT];
        CameraPose c = CameraPose.of(BODY, new JointAngles(d), acc);
        Vector3 v = c.toBody(new Polar(5, 0, 0));
        assertEquals(5 * Math.cos(a) + 0.155 * Math.sin(a), v.x(), 1e-6);
        assertEquals(-5 * Math.sin(a) + 0.155 * Math.cos(a), v.z(), 1e-6);
        assertEquals(0, v.y(), 1e-9);
    }

    /** Thesis 4.6 Walk to Ball: ground distance from the camera distance and height. */
    @Test
    void groundDistanceUsesTheCameraHeight() {
        CameraPose c = CameraPose.upright(BODY, 0, 0);
        double h = c.cameraHeight() - 0.042;
        assertEquals(3.0, c.groundDistance(Math.hypot(3.0, h), 0.042), 1e-9);
        assertEquals(0, c.groundDistance(0.1, 0.042), 0, "closer than the height: 0, never NaN");
    }

    @Test
    void missingJointsAndAccelerometerMeanUpright() {
        CameraPose c = CameraPose.of(BODY, JointAngles.none(), null);
        assertEquals(0.155, c.toBody(new Polar(1, 0, 0)).z(), 1e-9);
        CameraPose z = CameraPose.of(BODY, JointAngles.none(), Vector3.ZERO);
        assertEquals(1, z.toBody(new Polar(1, 0, 0)).x(), 1e-9);
    }
}

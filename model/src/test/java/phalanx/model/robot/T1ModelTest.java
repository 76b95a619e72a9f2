package phalanx.model.robot;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.comm.perception.Vector3;
import phalanx.model.field.MjField;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** The camera chain against real rcssservermj vision: seen markers land on their known world positions. */
class T1ModelTest {
    private static final Path RECORDING = Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt");

    @Test
    void everySeenMarkerOfTheRecordingMapsOntoItsWorldPosition() throws Exception {
        Map<String, Vector3> markers = MjField.SSIM.markers();
        MjPerceptionParser parser = new MjPerceptionParser();
        int checked = 0;
        double worst = 0;
        List<String> lines = Files.readAllLines(RECORDING);
        for (String line : lines) {
            MjPerception p = parser.parse(line);
            if (p.quat() == null || p.pos() == null) continue;
            double yaw = p.joints().get("q_hj1")[0], pitch = p.joints().get("q_hj2")[0];
            for (MjPerception.Seen s : p.seen()) {
                Vector3 truth = markers.get(s.name());
                if (truth == null) continue;
                double[] w = T1Model.seenToWorld(p.quat(), p.pos(), yaw, pitch, s.distance(), s.azimuth(), s.elevation());
                double err = Math.sqrt(sq(w[0] - truth.x()) + sq(w[1] - truth.y()) + sq(w[2] - truth.z()));
                // truncation: positions to 1 mm, angles to 0.01 deg (5 mm at 30 m), distances to 1 cm
                assertTrue(err < 0.1, s.name() + " at " + line.substring(0, 22) + " off by " + err + " m");
                worst = Math.max(worst, err);
                checked++;
            }
        }
        assertTrue(checked > 100, "only " + checked + " markers seen");
        System.out.printf("T1 camera chain: %d marker sightings, worst %.3f m%n", checked, worst);
    }

    @Test
    void headingAndUprightnessOfPlainQuaternions() {
        double s = Math.sqrt(0.5);
        assertEquals(-90, T1Model.headingDeg(new double[] {s, 0, 0, -s}), 1e-9);   // the recording's start pose
        assertEquals(0, T1Model.headingDeg(new double[] {1, 0, 0, 0}), 1e-9);
        assertEquals(1, T1Model.uprightness(new double[] {s, 0, 0, -s}), 1e-9);
        assertEquals(0, T1Model.uprightness(new double[] {s, s, 0, 0}), 1e-9);     // rolled 90 deg: lying on its side
        assertArrayEquals(new double[] {Math.PI / 2, 0}, T1Model.rollPitch(new double[] {s, s, 0, 0}), 1e-9);
        double h = Math.toRadians(10) / 2;                                               // 10 deg about y: leaning forward
        assertArrayEquals(new double[] {0, Math.toRadians(10)}, T1Model.rollPitch(new double[] {Math.cos(h), 0, Math.sin(h), 0}), 1e-9);
    }

    @Test
    void withoutYawKeepsRollAndPitchAndDropsTheHeading() {
        double[] q = {0.9, 0.1, -0.2, 0.38};   // some tilted, turned torso (normalised inside)
        double[] level = T1Model.withoutYaw(q);
        assertArrayEquals(T1Model.rollPitch(q), T1Model.rollPitch(level), 1e-9);
        assertEquals(0, T1Model.headingDeg(level), 1e-9);
    }

    @Test
    void aPointStraightAheadOfAnUprightRobotIsInFrontOfItsCamera() {
        double[] w = T1Model.seenToWorld(new double[] {1, 0, 0, 0}, new double[] {1, 2, 0.6735}, 0, 0, 2, 0, 0);
        // camera at x = 1 + 0.0625 + 0.05, z = 0.6735 + 0.243 + 0.06185 + 0.12
        assertArrayEquals(new double[] {3.1125, 2, 1.09835}, w, 1e-9);
    }

    private static double sq(double v) { return v * v; }
}

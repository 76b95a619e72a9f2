package phalanx.localization.filter;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.localization.LocalizationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.localization.vision.LandmarkSighting;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class EkfPoseFilterTest {
    private final FieldSpec field = FieldSpec.V066;

    private List<LandmarkSighting> see(Pose2 truth, Random noise, double sigma, Landmark... ls) {
        List<LandmarkSighting> out = new ArrayList<>();
        for (Landmark l : ls) {
            Vector3 p = field.landmark(l, Side.LEFT);
            Vector2 at = new Vector2(p.x(), p.y());
            Vector2 rel = truth.toRelative(at);
            out.add(new LandmarkSighting(l, at, rel.plus(new Vector2(noise.nextGaussian() * sigma, noise.nextGaussian() * sigma))));
        }
        return out;
    }

    @Test
    void startsFromTheFixAndAveragesNoiseAway() {
        EkfPoseFilter f = new EkfPoseFilter(LocalizationConfig.DEFAULT);
        Pose2 truth = new Pose2(-5, 2, 7);
        Random r = new Random(1);
        assertNull(f.pose());
        assertFalse(f.update(null, see(truth, r, 0.05, Landmark.F1R)), "no fix yet: one landmark cannot start it");
        f.update(new Pose2(-4.8, 2.2, 9), List.of());
        for (int i = 0; i < 60; i++) {
            f.predict(0, 0, 0);
            f.update(null, see(truth, r, 0.05, Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R));
        }
        assertEquals(-5, f.pose().x(), 0.03);
        assertEquals(2, f.pose().y(), 0.03);
        assertEquals(7, f.pose().thetaDeg(), 0.3);
        assertTrue(f.confidence() > 0.5);
    }

    @Test
    void oneLandmarkStillCorrectsOnceStarted() {
        EkfPoseFilter f = new EkfPoseFilter(LocalizationConfig.DEFAULT);
        Pose2 truth = new Pose2(0, 0, 0);
        f.update(new Pose2(0.2, 0, 0), List.of());
        for (int i = 0; i < 30; i++) assertTrue(f.update(null, see(truth, new Random(i), 0, Landmark.G1R)));
        assertEquals(0, f.pose().x(), 0.02, "G1R straight ahead fixes the distance along x");
    }

    @Test
    void gateDropsAWildLandmarkAndRestartsAfterAMove() {
        LocalizationConfig c = LocalizationConfig.DEFAULT;
        EkfPoseFilter f = new EkfPoseFilter(c);
        Pose2 truth = new Pose2(-1, -4, 90);
        f.update(truth, List.of());
        List<LandmarkSighting> wild = see(new Pose2(5, 5, 0), new Random(2), 0, Landmark.F1R);
        assertFalse(f.update(null, wild), "5 m off: outside the gate");
        assertEquals(-1, f.pose().x(), 1e-9);
        // Trainer move to (3, -4): the first frames are refused, then the filter restarts at the fix.
        Pose2 moved = new Pose2(3, -4, 90);
        for (int i = 1; i < c.relocateFrames(); i++)
            assertFalse(f.update(moved, see(moved, new Random(i), 0, Landmark.F1R, Landmark.G1R)));
        assertTrue(f.update(moved, see(moved, new Random(9), 0, Landmark.F1R, Landmark.G1R)));
        assertEquals(3, f.pose().x(), 1e-9);
    }

    @Test
    void odometryMovesThePoseInTheBodyFrame() {
        EkfPoseFilter f = new EkfPoseFilter(LocalizationConfig.DEFAULT);
        f.update(new Pose2(1, 1, 90), List.of());
        double before = f.positionSigma();
        for (int i = 0; i < 10; i++) f.predict(0.01, 0, 1);
        assertEquals(1, f.pose().x(), 0.01);
        assertEquals(1.1, f.pose().y(), 0.01);
        assertEquals(100, f.pose().thetaDeg(), 1e-9);
        assertTrue(f.positionSigma() > before, "uncertainty grows while walking blind");
    }
}

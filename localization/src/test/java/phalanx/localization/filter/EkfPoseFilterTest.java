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

    private static final Landmark[] FOUR = {Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R};

    /** A converged filter at the given pose. */
    private EkfPoseFilter converged(Pose2 at) {
        EkfPoseFilter f = new EkfPoseFilter(LocalizationConfig.DEFAULT);
        f.update(at, List.of());
        for (int i = 0; i < 30; i++) f.update(at, see(at, new Random(i), 0.01, FOUR));
        return f;
    }

    @Test
    void aMoveIsFollowedAtTheKthDisagreeingFrame() {
        int k = LocalizationConfig.DEFAULT.relocateFrames();
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(-2, 3, 30);
        EkfPoseFilter f = converged(a);
        assertEquals(1, f.starts());
        for (int i = 1; i < k; i++) {
            assertFalse(f.update(b, see(b, new Random(50 + i), 0.01, FOUR)), "frame " + i + " after the move");
            assertEquals(-4, f.pose().x(), 0.02, "not yet");
        }
        assertTrue(f.update(new Pose2(-2.03, 3.01, 30.2), see(b, new Random(60), 0.01, FOUR)));
        assertEquals(-2.015, f.pose().x(), 1e-9, "re-initialised at the mean of the two disagreeing frames' fixes");
        assertEquals(30.1, f.pose().thetaDeg(), 1e-9);
        assertEquals(2, f.starts());
        for (int i = 0; i < 20; i++) f.update(b, see(b, new Random(70 + i), 0.01, FOUR));
        assertEquals(-2, f.pose().x(), 0.02);
        assertEquals(30, f.pose().thetaDeg(), 0.5);
    }

    @Test
    void aSingleOutlierFrameDoesNotMoveTheBelief() {
        Pose2 a = new Pose2(-4, 1, 0), wrong = new Pose2(3, -2, 20);
        EkfPoseFilter f = converged(a);
        for (int round = 0; round < 10; round++) {
            assertFalse(f.update(wrong, see(wrong, new Random(round), 0.01, FOUR)), "an outlier frame");
            assertEquals(-4, f.pose().x(), 0.02);
            assertTrue(f.update(a, see(a, new Random(100 + round), 0.01, FOUR)));
        }
        assertEquals(1, f.starts(), "never re-initialised");
        assertEquals(1, f.pose().y(), 0.02);
    }

    @Test
    void farFramesThatDisagreeWithEachOtherDoNotRelocate() {
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(3, -2, 20), c = new Pose2(3, 2, 20);
        EkfPoseFilter f = converged(a);
        assertFalse(f.update(b, see(b, new Random(1), 0.01, FOUR)));
        assertFalse(f.update(c, see(c, new Random(2), 0.01, FOUR)), "4 m from the previous far fix");
        assertEquals(-4, f.pose().x(), 0.02);
        assertFalse(f.update(null, see(c, new Random(3), 0.01, Landmark.G1R)), "one landmark, no fix: the count stays");
        assertTrue(f.update(c, see(c, new Random(4), 0.01, FOUR)), "c twice in a row (frames with a fix)");
        assertEquals(2, f.pose().y(), 1e-9);
    }

    @Test
    void aFixFarOffWhileTheLandmarksAgreeIsNotAMove() {
        Pose2 a = new Pose2(-4, 1, 0), bad = new Pose2(-1, 1, 0);
        EkfPoseFilter f = converged(a);
        for (int i = 0; i < 5; i++) assertTrue(f.update(bad, see(a, new Random(i), 0.01, FOUR)), "the landmarks pass the gate");
        assertEquals(1, f.starts());
        assertEquals(-4, f.pose().x(), 0.02);
    }
}

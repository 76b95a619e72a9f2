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
        // Trainer move to (3, -4): the first frame there restarts the filter at its fix, its two landmarks
        // agreeing with it (issue 19).
        Pose2 moved = new Pose2(3, -4, 90);
        assertTrue(f.update(moved, see(moved, new Random(9), 0, Landmark.F1R, Landmark.G1R)));
        assertEquals(3, f.pose().x(), 1e-6);
        assertEquals(2, f.starts());
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

    /** Without the single-frame relocation: the relocateFrames rule alone (as before issue 19's second fix). */
    private static final LocalizationConfig FRAMES_ONLY = LocalizationConfig.DEFAULT.withRelocateResidual(Double.NaN, Double.NaN);

    /** A converged filter at the given pose. */
    private EkfPoseFilter converged(Pose2 at) {
        return converged(at, LocalizationConfig.DEFAULT);
    }

    private EkfPoseFilter converged(Pose2 at, LocalizationConfig c) {
        EkfPoseFilter f = new EkfPoseFilter(c);
        f.update(at, List.of());
        for (int i = 0; i < 30; i++) f.update(at, see(at, new Random(i), 0.01, FOUR));
        return f;
    }

    @Test
    void withoutTheSingleFrameRuleAMoveIsFollowedAtTheKthDisagreeingFrame() {
        int k = FRAMES_ONLY.relocateFrames();
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(-2, 3, 30);
        EkfPoseFilter f = converged(a, FRAMES_ONLY);
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
    void aSingleOutlierFrameWhoseLandmarksDisagreeDoesNotMoveTheBelief() {
        Pose2 a = new Pose2(-4, 1, 0), wrong = new Pose2(3, -2, 20);
        EkfPoseFilter f = converged(a);
        for (int round = 0; round < 10; round++) {
            assertFalse(f.update(wrong, skewed(see(wrong, new Random(round), 0.01, FOUR), 3, 1.0)), "an outlier frame");
            assertEquals(-4, f.pose().x(), 0.02);
            assertTrue(f.update(a, see(a, new Random(100 + round), 0.01, FOUR)));
        }
        assertEquals(1, f.starts(), "never re-initialised");
        assertEquals(1, f.pose().y(), 0.02);
    }

    @Test
    void withoutTheSingleFrameRuleFarFramesThatDisagreeWithEachOtherDoNotRelocate() {
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(3, -2, 20), c = new Pose2(3, 2, 20);
        EkfPoseFilter f = converged(a, FRAMES_ONLY);
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

    /** The sightings with landmark i's ground vector moved by dx metres (a frame whose landmarks disagree). */
    private static List<LandmarkSighting> skewed(List<LandmarkSighting> seen, int i, double dx) {
        List<LandmarkSighting> out = new ArrayList<>(seen);
        LandmarkSighting l = out.get(i);
        out.set(i, new LandmarkSighting(l.landmark(), l.position(), l.relative().plus(new Vector2(dx, 0))));
        return out;
    }

    /**
     * Issue 19: one frame far from the belief whose landmarks all agree with its fix re-initialises the filter
     * there at once (a trainer move): with four landmarks and with two. Before the fix the first such frame was
     * refused and the second restarted it (relocateFrames = 2).
     */
    @Test
    void aFarFrameWhoseLandmarksAgreeReinitialisesAtOnce() {
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(3, -2, 20), fix = new Pose2(3.02, -2.01, 20.1);
        EkfPoseFilter f = converged(a);
        assertTrue(f.update(fix, see(b, new Random(5), 0.01, FOUR)), "the first frame after the move");
        assertEquals(2, f.starts());
        // At the frame's fix, then corrected by the frame's own landmarks: within 2 cm / 0.2 degrees of b.
        assertEquals(3, f.pose().x(), 0.02, "at the frame's fix");
        assertEquals(-2, f.pose().y(), 0.02);
        assertEquals(20, f.pose().thetaDeg(), 0.2);
        for (int i = 0; i < 20; i++) f.update(b, see(b, new Random(30 + i), 0.01, FOUR));
        assertEquals(3, f.pose().x(), 0.02);
        assertEquals(2, f.starts(), "and it goes on from there");

        EkfPoseFilter two = converged(a);
        Pose2 c = new Pose2(-1, -4, 90);
        assertTrue(two.update(c, see(c, new Random(6), 0.01, Landmark.F1R, Landmark.G1R)), "two landmarks that agree");
        assertEquals(-1, two.pose().x(), 0.02);
    }

    /**
     * The price of following a move at once: a wrong frame whose landmarks all agree with a far pose is taken
     * too, and the next good frame takes the belief back (both are one frame). With a wrong camera pose the
     * landmarks do not agree (the test above); no such frame is in the recordings (localization/README.md).
     */
    @Test
    void aWrongButConsistentFrameIsUndoneByTheNextGoodOne() {
        Pose2 a = new Pose2(-4, 1, 0), wrong = new Pose2(3, -2, 20);
        EkfPoseFilter f = converged(a);
        assertTrue(f.update(wrong, see(wrong, new Random(1), 0.01, FOUR)));
        assertEquals(3, f.pose().x(), 0.02);
        assertTrue(f.update(a, see(a, new Random(2), 0.01, FOUR)));
        assertEquals(-4, f.pose().x(), 0.02);
        assertEquals(3, f.starts());
    }

    @Test
    void theSingleFrameRuleCanBeTurnedOff() {
        Pose2 a = new Pose2(-4, 1, 0), b = new Pose2(3, -2, 20);
        EkfPoseFilter f = converged(a, FRAMES_ONLY);
        assertFalse(f.update(b, see(b, new Random(5), 0.01, FOUR)));
        assertEquals(-4, f.pose().x(), 0.02);
    }
}

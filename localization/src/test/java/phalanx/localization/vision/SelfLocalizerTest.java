package phalanx.localization.vision;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.localization.LocalizationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class SelfLocalizerTest {
    private final FieldSpec field = FieldSpec.V066;

    private LandmarkSighting seen(Pose2 truth, Landmark l, Side side) {
        Vector3 p = field.landmark(l, side);
        Vector2 at = new Vector2(p.x(), p.y());
        return new LandmarkSighting(l, at, truth.toRelative(at));
    }

    @Test
    void exactPairGivesTheTruePose() {
        Pose2 truth = new Pose2(-5, 2, 30);
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT);
        Pose2 p = s.pair(seen(truth, Landmark.F1R, Side.LEFT), seen(truth, Landmark.G1R, Side.LEFT));
        assertNotNull(p);
        assertEquals(-5, p.x(), 1e-6);
        assertEquals(2, p.y(), 1e-6);
        assertEquals(30, p.thetaDeg(), 1e-6);
    }

    /** The wrong candidate is the true one mirrored across the line through the two landmarks. */
    @Test
    void rejectsTheMirrorCandidateByTheBearings() {
        Pose2 truth = new Pose2(10, 0, 0);
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT.withPairWeighting(LocalizationConfig.PairWeighting.EQUAL));
        // G1R and F2R lie on the line x = 15: the mirror candidate (20, 0) is off the field.
        Pose2 p = s.pair(seen(truth, Landmark.G1R, Side.LEFT), seen(truth, Landmark.F2R, Side.LEFT));
        assertEquals(10, p.x(), 1e-6);
        assertEquals(0, p.y(), 1e-6);
        // F1L and F2R lie on a diagonal: the mirror of (0, 5) is (-4.62, -1.92), on the field too; the bearings decide.
        Pose2 t2 = new Pose2(0, 5, -90);
        Pose2 q = s.pair(seen(t2, Landmark.F1L, Side.LEFT), seen(t2, Landmark.F2R, Side.LEFT));
        assertEquals(0, q.x(), 1e-6);
        assertEquals(5, q.y(), 1e-6);
        assertEquals(-90, q.thetaDeg(), 1e-6);
    }

    @Test
    void rightSideTeamUsesItsOwnFrame() {
        // S6: a right-side robot at field (10, 4) facing -150° is at own (-10, -4) facing 30°.
        Pose2 own = new Pose2(-10, -4, 30);
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT);
        List<LandmarkSighting> l = new ArrayList<>();
        for (Landmark m : new Landmark[] {Landmark.F1L, Landmark.G1L, Landmark.G2L}) l.add(seen(own, m, Side.RIGHT));
        Pose2 p = s.locate(l);
        assertEquals(-10, p.x(), 1e-6);
        assertEquals(-4, p.y(), 1e-6);
        assertEquals(30, p.thetaDeg(), 1e-6);
    }

    @Test
    void averagesAllPairsAndNeedsTwoLandmarks() {
        Pose2 truth = new Pose2(3, -4, 90);
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT.withPairWeighting(LocalizationConfig.PairWeighting.EQUAL));
        List<LandmarkSighting> l = new ArrayList<>();
        l.add(seen(truth, Landmark.F1R, Side.LEFT));
        assertNull(s.locate(l), "one landmark: no fix");
        assertNull(s.locate(List.of()), "no landmark: no fix");
        l.add(seen(truth, Landmark.G1R, Side.LEFT));
        l.add(seen(truth, Landmark.F1L, Side.LEFT));
        // Distort one sighting's distance by 0.3 m: the pairs disagree, the mean lies between them.
        LandmarkSighting f1l = l.get(2);
        l.set(2, new LandmarkSighting(f1l.landmark(), f1l.position(), f1l.relative().times(1 + 0.3 / f1l.relative().norm())));
        Pose2 p = s.locate(l);
        Pose2 a = s.pair(l.get(0), l.get(1)), b = s.pair(l.get(0), l.get(2)), c = s.pair(l.get(1), l.get(2));
        assertEquals((a.x() + b.x() + c.x()) / 3, p.x(), 1e-9);
        assertEquals((a.y() + b.y() + c.y()) / 3, p.y(), 1e-9);
    }

    @Test
    void circlesThatDoNotMeetGiveNoFix() {
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT);
        Vector3 a = field.landmark(Landmark.F1R), b = field.landmark(Landmark.F2R);
        // 20 m apart, both seen 3 m away: impossible.
        assertNull(s.pair(new LandmarkSighting(Landmark.F1R, new Vector2(a.x(), a.y()), new Vector2(3, 0)),
                new LandmarkSighting(Landmark.F2R, new Vector2(b.x(), b.y()), new Vector2(0, 3))));
    }

    /** Issue 19: the check that lets one frame re-initialise the self belief. */
    @Test
    void consistentWhenEveryLandmarkFitsTheFix() {
        Pose2 truth = new Pose2(-5, 2, 30);
        SelfLocalizer s = new SelfLocalizer(field, LocalizationConfig.DEFAULT);
        List<LandmarkSighting> four = new ArrayList<>(List.of(seen(truth, Landmark.F1R, Side.LEFT), seen(truth, Landmark.G1R, Side.LEFT),
                seen(truth, Landmark.G2R, Side.LEFT), seen(truth, Landmark.F2R, Side.LEFT)));
        Pose2 fix = s.locate(four);
        assertTrue(SelfLocalizer.consistent(fix, four, 0.1, 0.02));
        assertTrue(SelfLocalizer.consistent(new Pose2(-5.05, 2.03, 30.1), four, 0.1, 0.02), "a few cm off still fits");
        assertFalse(SelfLocalizer.consistent(new Pose2(-4, 2, 30), four, 0.1, 0.02), "1 m off does not");
        assertFalse(SelfLocalizer.consistent(new Pose2(-5, 2, 35), four, 0.1, 0.02), "5 degrees off at 14-16 m does not");
        // One landmark 1 m off where it should be (a wrong distance): the frame's landmarks disagree.
        LandmarkSighting g = four.get(2);
        four.set(2, new LandmarkSighting(g.landmark(), g.position(), g.relative().plus(new Vector2(1.0, 0))));
        assertFalse(SelfLocalizer.consistent(s.locate(four), four, 0.1, 0.02));
        assertFalse(SelfLocalizer.consistent(truth, four.subList(0, 1), 0.1, 0.02), "one landmark proves nothing");
        assertFalse(SelfLocalizer.consistent(null, four, 0.1, 0.02));
        assertFalse(SelfLocalizer.consistent(truth, four.subList(0, 2), Double.NaN, Double.NaN), "NaN: off");
    }
}

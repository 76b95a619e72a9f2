package phalanx.localization.filter;

import org.junit.jupiter.api.Test;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

/** Thesis 4.4.3, Algorithm 1, step by step. */
class LocalizationFilterTest {

    @Test
    void firstEstimateIsTakenAndAgreeingOnesAreAveraged() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        assertNull(f.pose());
        assertTrue(f.add(new Pose2(1, 1, 10)));
        assertTrue(f.add(new Pose2(1.2, 1, 20)));
        Pose2 p = f.pose();
        assertEquals(1.1, p.x(), 1e-9);
        assertEquals(1, p.y(), 1e-9);
        assertEquals(15, p.thetaDeg(), 1e-9);
    }

    @Test
    void anOutlierIsIgnoredAndRemovesTheOldestEntry() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        f.add(new Vector2(0, 0));
        f.add(new Vector2(0.2, 0));
        f.add(new Vector2(0.4, 0));
        assertFalse(f.add(new Vector2(5, 5)));
        assertEquals(2, f.size());
        assertEquals(0.3, f.position().x(), 1e-9, "the oldest (0, 0) went, the outlier was not added");
        assertEquals(1, f.rejected());
    }

    @Test
    void orientationCountsForPosesAcrossTheSeam() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        f.add(new Pose2(0, 0, 175));
        assertTrue(f.add(new Pose2(0, 0, -175)), "175° and -175° are 10° apart");
        assertEquals(180, Math.abs(f.pose().thetaDeg()), 1e-9);
        assertFalse(f.add(new Pose2(0, 0, 150)), "same place, 30° off: disagrees");
    }

    @Test
    void aPersistentNewLocationReplacesTheBelief() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        for (int i = 0; i < 10; i++) f.add(new Vector2(0, 0));
        assertEquals(10, f.size());
        // The robot was moved: ten disagreeing estimates empty the queue, the eleventh starts a new belief.
        for (int i = 0; i < 10; i++) assertFalse(f.add(new Vector2(4, 0)));
        assertTrue(f.isEmpty());
        assertTrue(f.add(new Vector2(4, 0)));
        assertEquals(4, f.position().x(), 1e-9);
    }

    @Test
    void queueKeepsTheMaxSizeMostRecent() {
        LocalizationFilter f = new LocalizationFilter(3, 10, 15);
        for (int i = 1; i <= 5; i++) f.add(new Vector2(i, 0));
        assertEquals(3, f.size());
        assertEquals(4, f.position().x(), 1e-9, "mean of 3, 4, 5");
    }

    @Test
    void odometryShiftMovesQueuedPosesInTheirOwnFrame() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        f.add(new Pose2(1, 1, 90));
        f.shift(0.5, 0, 10);      // half a metre forward (= +y when facing 90°), turned 10°
        Pose2 p = f.pose();
        assertEquals(1, p.x(), 1e-9);
        assertEquals(1.5, p.y(), 1e-9);
        assertEquals(100, p.thetaDeg(), 1e-9);
    }

    @Test
    void nonFiniteEstimatesAreIgnored() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        assertFalse(f.add(new Vector2(Double.NaN, 0)));
        assertFalse(f.add(new Pose2(0, 0, Double.POSITIVE_INFINITY)));
        assertTrue(f.isEmpty());
    }

    /** Relocation as the self filter runs it (LocalizationConfig.DEFAULT: k = 2, 0.5 m / 15° far, 0.5 m / 15° spread). */
    private static LocalizationFilter relocating() {
        return new LocalizationFilter(10, 0.5, 15, 2, 0.5, 15, 0.5, 15);
    }

    @Test
    void twoAgreeingFarRefusalsReplaceTheQueue() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Pose2(-1, -4, 90));
        assertEquals(1, f.starts());
        // Trainer move to (3, -4): the first estimate there is refused as in Algorithm 1 ...
        assertFalse(f.add(new Pose2(3.02, -4, 90)));
        assertEquals(-1, f.pose().x(), 1e-9, "one far estimate does not move the belief");
        assertEquals(9, f.size(), "Algorithm 1, line 8: the oldest went");
        assertEquals(1, f.pending());
        // ... the second, 0.04 m from the first, relocates: the queue is the two of them.
        assertTrue(f.add(new Pose2(2.98, -4, 90)));
        assertEquals(3, f.pose().x(), 1e-9);
        assertEquals(2, f.size());
        assertEquals(2, f.starts());
        assertEquals(1, f.relocations());
        assertEquals(0, f.pending());
        assertTrue(f.add(new Pose2(3, -4.1, 90)), "and the filter goes on from there");
    }

    @Test
    void aSingleOutlierNeverMovesTheBelief() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Pose2(0, 0, 0));
        for (int round = 0; round < 20; round++) {
            assertFalse(f.add(new Pose2(6, 2, 40)), "an outlier frame between good ones");
            assertTrue(f.add(new Pose2(0.01, 0, 0)));
            assertTrue(f.add(new Pose2(-0.01, 0, 0)));
            assertEquals(0, f.pose().x(), 0.011);
            assertEquals(0, f.pose().y(), 1e-9);
        }
        assertEquals(0, f.relocations());
        assertEquals(1, f.starts());
    }

    @Test
    void farRefusalsThatDisagreeWithEachOtherDoNotRelocate() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Vector2(0, 0));
        assertFalse(f.add(new Pose2(4, 0, 0)));
        assertFalse(f.add(new Pose2(4, 3, 0)), "3 m from the previous refused one: the count starts again from it");
        assertEquals(0, f.pose().x(), 1e-9);
        assertEquals(0, f.relocations());
        assertTrue(f.add(new Pose2(4, 3.1, 0)), "two in a row that agree");
        assertEquals(4, f.pose().x(), 1e-9);
        assertEquals(3.05, f.pose().y(), 1e-9);
    }

    @Test
    void anAgreeingEstimateBetweenTwoFarOnesResetsTheCount() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Pose2(0, 0, 0));
        assertFalse(f.add(new Pose2(4, 0, 0)));
        assertTrue(f.add(new Pose2(0, 0, 0)));
        assertFalse(f.add(new Pose2(4, 0, 0)), "not two in a row");
        assertEquals(0, f.relocations());
    }

    @Test
    void aTurnInPlaceRelocatesToo() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Pose2(2, 2, 0));
        assertFalse(f.add(new Pose2(2, 2, 90)));
        assertTrue(f.add(new Pose2(2, 2, 91)));
        assertEquals(90.5, f.pose().thetaDeg(), 1e-9);
    }

    @Test
    void theThesisFilterAndTheBallHaveNoRelocation() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, Double.NaN);
        for (int i = 0; i < 10; i++) f.add(new Vector2(0, 0));
        for (int i = 0; i < 9; i++) assertFalse(f.add(new Vector2(4, 0)), "refusal " + (i + 1));
        assertEquals(0, f.relocations());
        assertEquals(1, f.starts());
        assertFalse(f.add(new Vector2(4, 0)));
        assertTrue(f.isEmpty());
        assertTrue(f.add(new Vector2(4, 0)));
        assertEquals(2, f.starts(), "a new belief after the queue emptied counts as a start");
    }

    /** Issue 19: a far estimate flagged consistent (every landmark of its frame fits it) replaces the queue at once. */
    @Test
    void aConsistentFarEstimateRelocatesAtOnce() {
        LocalizationFilter f = relocating();
        for (int i = 0; i < 10; i++) f.add(new Pose2(-1, -4, 90));
        assertTrue(f.add(new Pose2(3.02, -4, 90), true));
        assertEquals(3.02, f.pose().x(), 1e-9);
        assertEquals(1, f.size());
        assertEquals(2, f.starts());
        assertEquals(1, f.relocations());
        assertEquals(0, f.pending());
        assertTrue(f.add(new Pose2(2.98, -4, 90), true), "an agreeing one is queued as before");
        assertEquals(2, f.size());
        assertEquals(1, f.relocations());
    }

    @Test
    void aConsistentEstimateChangesNothingWithoutRelocation() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15);
        for (int i = 0; i < 10; i++) f.add(new Pose2(0, 0, 0));
        assertFalse(f.add(new Pose2(4, 0, 0), true), "the thesis's filter: refused");
        assertEquals(0, f.relocations());
    }

    /**
     * Issue 19, turn-head: the walk's odometry reports 1.20°/cycle where the robot turns 1.10°. Fixes at the true
     * heading every 3rd cycle, the queue moved by the reported turn: with every fix counting the same (Algorithm 1)
     * the average runs ahead of the turn by the odometry error of its older entries (here 2.5°); weighed by the motion
     * each entry was moved by, the newest fixes dominate and it stays within 0.25°.
     */
    @Test
    void fixesMovedFarByOdometryCountLess() {
        LocalizationFilter plain = new LocalizationFilter(10, 0.5, 15);
        LocalizationFilter weighed = new LocalizationFilter(10, 0.5, 15).weighByMotion(0.05, 0.2, 0.1);
        double truth = 0;
        for (int k = 1; k <= 60; k++) {
            truth += 1.10;
            plain.shift(0, 0, 1.20);
            weighed.shift(0, 0, 1.20);
            if (k % 3 == 0) {
                assertTrue(plain.add(new Pose2(0, 0, truth)));
                assertTrue(weighed.add(new Pose2(0, 0, truth)));
            }
        }
        assertEquals(10, plain.size());
        // The plain mean: entries moved 0, 3, ..., 27 cycles by a 0.1°/cycle error, 1.35° ahead on average.
        assertEquals(1.35, plain.pose().thetaDeg() - truth, 0.01);
        assertEquals(0, weighed.pose().thetaDeg() - truth, 0.25, "the newest fixes dominate while turning");
    }

    @Test
    void withoutMotionTheWeighedAverageIsAlgorithm1s() {
        LocalizationFilter f = new LocalizationFilter(10, 0.5, 15).weighByMotion(0.05, 0.2, 0.1);
        f.add(new Pose2(1, 1, 10));
        f.add(new Pose2(1.2, 1.4, 20));
        f.add(new Pose2(1.1, 0.9, 12));
        assertEquals(1.1, f.pose().x(), 1e-9);
        assertEquals(1.1, f.pose().y(), 1e-9);
        assertEquals(14, f.pose().thetaDeg(), 0.05);
        // Walking: the entry moved 1 m (0.1 m odometry error, twice the fix's 0.05 m) weighs 1/5 of a fresh one.
        f.clear();
        f.add(new Pose2(0, 0, 0));
        f.shift(1, 0, 0);
        f.add(new Pose2(1.5, 0, 0));
        assertEquals((1 * 1 + 1.5 * 5) / 6.0, f.pose().x(), 1e-9);
    }

    @Test
    void motionWeightingRefusesBadConstants() {
        assertThrows(IllegalArgumentException.class, () -> new LocalizationFilter(10, 0.5, 15).weighByMotion(0, 0.2, 0.1));
        assertThrows(IllegalArgumentException.class, () -> new LocalizationFilter(10, 0.5, 15).weighByMotion(0.05, 0.2, -1));
    }
}

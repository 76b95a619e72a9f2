package phalanx.localization.tracking;

import org.junit.jupiter.api.Test;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

/** Thesis 4.6 Track Moving Object: two sets of five observations, five observations apart. */
class MovingObjectTrackerTest {

    @Test
    void constantVelocityIsRecovered() {
        MovingObjectTracker t = new MovingObjectTracker(5, 5, 1.0);
        for (int i = 0; i < 9; i++) t.observe(new Vector2(1 + 2.0 * i * 0.06, -0.5 * i * 0.06), i * 0.06);
        assertFalse(t.ready(), "nine observations: the second set is not full");
        assertNull(t.velocity());
        t.observe(new Vector2(1 + 2.0 * 9 * 0.06, -0.5 * 9 * 0.06), 9 * 0.06);
        Vector2 v = t.velocity();
        assertEquals(2.0, v.x(), 1e-9);
        assertEquals(-0.5, v.y(), 1e-9);
    }

    @Test
    void usesTheLatestTenObservations() {
        MovingObjectTracker t = new MovingObjectTracker(5, 5, 1.0);
        // Still for 10 observations, then moving at 1 m/s for 10 more: only the moving ones count.
        for (int i = 0; i < 10; i++) t.observe(new Vector2(0, 0), i * 0.06);
        assertEquals(0, t.velocity().norm(), 1e-12);
        for (int i = 10; i < 20; i++) t.observe(new Vector2((i - 9) * 0.06, 0), i * 0.06);
        assertEquals(1.0, t.velocity().x(), 1e-9);
    }

    @Test
    void aGapRestartsAndBadObservationsAreIgnored() {
        MovingObjectTracker t = new MovingObjectTracker(5, 5, 1.0);
        for (int i = 0; i < 10; i++) t.observe(new Vector2(i, 0), i * 0.06);
        assertTrue(t.ready());
        t.observe(new Vector2(0, 0), 5.0);                 // seen again 4.5 s later
        assertFalse(t.ready());
        t.observe(new Vector2(Double.NaN, 0), 5.1);
        t.observe(null, 5.2);
        t.observe(new Vector2(1, 1), 4.0);                 // older than the last: ignored
        assertFalse(t.ready());
    }
}

package phalanx.localization.team;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.model.field.Vector2;

/** Clustering cases worked out by hand (thesis 5.4, Figure 5.3). */
class BallFusionClusterTest {
    private static final BallFusion FUSION = new BallFusion(1.0, 3.0);
    private static Vector2 fuse(Vector2... o) { return FUSION.fuse(List.of(o)); }

    @Test
    void noObservationGivesNull() {
        assertNull(FUSION.fuse(List.of()));
    }

    @Test
    void closeObservationsAverage() {
        Vector2 b = fuse(new Vector2(1, 1), new Vector2(1.4, 1.2));
        assertEquals(1.2, b.x(), 1e-12);
        assertEquals(1.1, b.y(), 1e-12);
    }

    @Test
    void outlierWeighsOneOverTwentyEight() {
        // Cluster of three around (0,0) (weight 27) and one observation at (10,0) (weight 1):
        // ball = (27·0 + 1·10) / 28 in x.
        Vector2 b = fuse(new Vector2(-0.1, 0), new Vector2(0.1, 0), new Vector2(0, 0), new Vector2(10, 0));
        assertEquals(10.0 / 28, b.x(), 1e-12);
        assertEquals(0, b.y(), 1e-12);
    }

    @Test
    void twoEqualClustersMeetHalfway() {
        Vector2 b = fuse(new Vector2(0, 0), new Vector2(4, 0));
        assertEquals(2, b.x(), 1e-12);
    }

    @Test
    void observationJoinsTheLargerOfTwoReachableClusters() {
        // Clusters {(0,0),(0.1,0)} (mean 0.05) and {(1.5,0)}; (0.8,0) is within 1 m of both means and joins
        // the pair, whose mean becomes 0.3; the ball is (27·0.3 + 1·1.5)/28.
        Vector2 b = fuse(new Vector2(0, 0), new Vector2(0.1, 0), new Vector2(1.5, 0), new Vector2(0.8, 0));
        assertEquals((27 * 0.3 + 1.5) / 28, b.x(), 1e-12);
    }
}

package phalanx.localization.team;

import org.junit.jupiter.api.Test;
import phalanx.model.field.Vector2;

import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Thesis 5.4: clusters within 1 m, weights |s|^3, weighted mean of the representatives. */
class BallFusionTest {
    private final BallFusion fusion = new BallFusion(1.0, 3);

    @Test
    void threeAgreeingObservationsOutweighOneStray() {
        Vector2 fused = fusion.fuse(List.of(new Vector2(0, 0), new Vector2(0.2, 0), new Vector2(5, 5), new Vector2(0.4, 0)));
        // Clusters: {(0,0),(0.2,0),(0.4,0)} mean (0.2, 0), weight 27; {(5,5)} weight 1.
        assertEquals((27 * 0.2 + 5) / 28, fused.x(), 1e-12);
        assertEquals(5.0 / 28, fused.y(), 1e-12);
    }

    @Test
    void anObservationJoinsTheLargestClusterInReach() {
        // (0,0),(0,0.1) form a cluster of 2; (1.4,0) starts its own; (0.7,0) is within 1 m of both
        // representatives (0, 0.05) and (1.4, 0) and joins the larger one.
        Vector2 fused = fusion.fuse(List.of(new Vector2(0, 0), new Vector2(0, 0.1), new Vector2(1.4, 0), new Vector2(0.7, 0)));
        double bigX = 0.7 / 3, bigY = 0.1 / 3;
        assertEquals((27 * bigX + 1.4) / 28, fused.x(), 1e-12);
        assertEquals(27 * bigY / 28, fused.y(), 1e-12);
    }

    @Test
    void nothingUsableGivesNoBelief() {
        assertNull(fusion.fuse(List.of()));
        assertNull(fusion.fuse(Arrays.asList(null, new Vector2(Double.NaN, 1))));
        assertEquals(new Vector2(2, 3), fusion.fuse(Arrays.asList(null, new Vector2(2, 3))));
    }

    @Test
    void typeBPlayerStandsBehindItsBallReport() {
        Vector2 p = BallFusion.typeBPosition(new Vector2(5, -1), 2, 90);
        assertEquals(5, p.x(), 1e-12);
        assertEquals(-3, p.y(), 1e-12);
        assertNull(BallFusion.typeBPosition(new Vector2(5, -1), -1, 0));
        assertNull(BallFusion.typeBPosition(null, 1, 0));
    }
}

package phalanx.coordination.features;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.CollisionConfig;
import phalanx.model.field.FieldSpec;

class FeaturesTest {
    private static final CollisionConfig C = CollisionConfig.THESIS;

    @Test
    void fieldUtilityIsXTimesDistanceFromTheSideLine() {
        assertEquals(150, FieldUtility.of(15, 0, FieldSpec.V066), 1e-12);
        assertEquals(-150, FieldUtility.of(-15, 0, FieldSpec.V066), 1e-12);
        assertEquals(5 * 6, FieldUtility.of(5, -4, FieldSpec.V066), 1e-12);
        assertEquals(0, FieldUtility.of(5, 10, FieldSpec.V066), 1e-12);
        assertEquals(3 * 7, FieldUtility.of(3, 0, FieldSpec.V065), 1e-12);
    }

    @Test
    void crossingMidwayCostsOneHundred() {
        // An X: both routes reach (0,0) after 1.414 m.
        assertEquals(100, RouteCollision.cost(-1, -1, 1, 1, -1, 1, 1, -1, C), 1e-12);
    }

    @Test
    void crossingFarFromOneStartCostsTwo() {
        // Route 1 reaches (0,0) after 1 m, route 2 after 4 m: |1 - 4| > 1.5.
        assertEquals(2, RouteCollision.cost(-1, 0, 1, 0, 0, -4, 0, 1, C), 1e-12);
        // |1 - 2.4| = 1.4 is still "equidistant".
        assertEquals(100, RouteCollision.cost(-1, 0, 1, 0, 0, -2.4, 0, 1, C), 1e-12);
    }

    @Test
    void routesThatDoNotMeetCostNothing() {
        assertEquals(0, RouteCollision.cost(0, 0, 1, 0, 2, -1, 2, 1, C));
        assertEquals(0, RouteCollision.cost(0, 0, 1, 0, 0, 1, 1, 1, C));       // parallel
        assertEquals(0, RouteCollision.cost(0, 0, 0, 0, -1, 0, 1, 0, C));      // zero length
        assertFalse(RouteCollision.crosses(0, 0, 1, 0, 2, -1, 2, 1));
        assertTrue(RouteCollision.crosses(-1, -1, 1, 1, -1, 1, 1, -1));
    }
}

package phalanx.coordination.formation;

import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class StretchedFormationTest {
    private final StretchedFormation f = new StretchedFormation(MjField.SSIM, FormationConfig.DEFAULT);

    @Test
    void sevenRolesEachTheSimSparkSpotStretchedByTheFieldRatio() {
        Formation small = FormationGenerator.generate(new Vector2(3, -2), FieldSpec.V066, FormationConfig.DEFAULT);
        Formation big = f.generate(new Vector2(3 * 55 / 30.0, -2 * 36 / 20.0));
        assertEquals(List.of(Role.GK, Role.DL, Role.DC, Role.DR, Role.ML, Role.MR, Role.FC), List.copyOf(big.positions().keySet()));
        for (Role r : big.positions().keySet()) {
            assertEquals(small.position(r).x() * 55 / 30.0, big.position(r).x(), 1e-9, r.name());
            assertEquals(small.position(r).y() * 36 / 20.0, big.position(r).y(), 1e-9, r.name());
        }
    }

    @Test
    void kickOffSpotsAreInOurHalfInsideTheFieldWithTheKeeperNearOurGoal() {
        Formation k = f.generate(Vector2.ZERO);
        for (var e : k.positions().entrySet()) {
            Vector2 p = e.getValue();
            assertTrue(p.x() < 0 && Math.abs(p.x()) < 27.5 && Math.abs(p.y()) < 18, e.getKey() + " at " + p);
        }
        assertTrue(k.position(Role.GK).x() < -25, "keeper at " + k.position(Role.GK));
        assertEquals(Role.GK, f.role(1));
        assertEquals(Role.FC, f.role(7));
    }
}

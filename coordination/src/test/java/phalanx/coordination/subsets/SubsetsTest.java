package phalanx.coordination.subsets;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.coordination.Mode;
import phalanx.coordination.beliefs.BeliefsUpdate;
import phalanx.coordination.beliefs.GlobalBeliefs;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

class SubsetsTest {
    /** Ball at the origin; player i stands i metres from it on the x axis; 5 is lost, 6 lies on the ground. */
    private static GlobalBeliefs beliefs() {
        return BeliefsUpdate.update(new TeamBeliefs(FieldSpec.V066, List.of(
                PlayerReport.complete(1, new Pose2(-14, 0, 0), Vector2.ZERO),
                PlayerReport.located(2, new Pose2(-2, 0, 0)),
                PlayerReport.located(3, new Pose2(3, 0, 0)),
                PlayerReport.located(4, new Pose2(-4, 0, 0)),
                PlayerReport.lost(5),
                PlayerReport.located(6, new Pose2(0.5, 0, 0)).asFallen(),
                PlayerReport.located(7, new Pose2(7, 0, 0)),
                PlayerReport.ballOnly(8, 1.0, 0, 0),
                PlayerReport.located(9, new Pose2(-9, 0, 0)))), 1, 3, null);
    }

    @Test
    void activeAreTheThreeNearestTheBallStandingAndLocated() {
        Subsets s = Subsets.split(beliefs(), Mode.ACTIVE, 1, 3);
        assertEquals(1, s.goalkeeper());
        assertEquals(List.of(8, 2, 3), s.active());          // 1 m, 2 m, 3 m; 6 is nearer but fallen
        assertEquals(List.of(5, 6), s.inactive());
        assertEquals(List.of(4, 7, 9), s.support());
        assertEquals(Subset.ACTIVE, s.of(2));
        assertEquals(Subset.INACTIVE, s.of(5));
        assertEquals(Subset.GOALKEEPER, s.of(1));
        assertNull(s.of(10));
    }

    @Test
    void supportModeHasNoActivePlayers() {
        Subsets s = Subsets.split(beliefs(), Mode.SUPPORT, 1, 3);
        assertTrue(s.active().isEmpty());
        assertEquals(List.of(2, 3, 4, 7, 8, 9), s.support());
        assertEquals(List.of(5, 6), s.inactive());
    }

    @Test
    void waitModeMakesEveryFieldPlayerInactive() {
        Subsets s = Subsets.split(beliefs(), Mode.WAIT, 1, 3);
        assertEquals(1, s.goalkeeper());
        assertEquals(8, s.inactive().size());
        assertTrue(s.active().isEmpty() && s.support().isEmpty());
    }

    @Test
    void demoteMovesActivePlayersToSupport() {
        Subsets s = Subsets.split(beliefs(), Mode.ACTIVE, 1, 3).demote(List.of(3));
        assertEquals(List.of(8, 2), s.active());
        assertEquals(List.of(3, 4, 7, 9), s.support());
    }
}

package phalanx.coordination.schedule;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import phalanx.coordination.Coordinator;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

class CoordinationScheduleTest {
    private static final TeamBeliefs TEAM = new TeamBeliefs(FieldSpec.V066, List.of(
            PlayerReport.complete(1, new Pose2(-14, 0, 0), new Vector2(3, 1)),
            PlayerReport.complete(2, new Pose2(1, 1, 0), new Vector2(3, 1)),
            PlayerReport.located(3, new Pose2(-2, -3, 0)),
            PlayerReport.located(4, new Pose2(0, 4, 0)),
            PlayerReport.located(5, new Pose2(-8, 0, 0)),
            PlayerReport.lost(6)));

    @Test
    void thesisScheduleTakesSixCyclesAndGivesTheSamePlan() {
        Coordinator c = new Coordinator();
        CoordinationSchedule s = new CoordinationSchedule(c, false);
        assertFalse(s.busy());
        assertEquals(Optional.empty(), s.cycle());
        s.start(TEAM, Mode.ACTIVE, Memory.NONE);
        for (int cycle = 1; cycle <= 5; cycle++) {
            assertTrue(s.busy());
            assertEquals(Optional.empty(), s.cycle(), "cycle " + cycle);
        }
        TeamPlan plan = s.cycle().orElseThrow();
        assertFalse(s.busy());
        assertEquals(c.coordinate(TEAM, Mode.ACTIVE, Memory.NONE).assignments(), plan.assignments());
    }

    @Test
    void singleCycleRunsAllPhasesAtOnce() {
        CoordinationSchedule s = new CoordinationSchedule(new Coordinator(), true);
        s.start(TEAM, Mode.ACTIVE, Memory.NONE);
        assertTrue(s.cycle().isPresent());
        assertFalse(s.busy());
    }

    @Test
    void fittingPicksASingleCycleWhenTheRoundFitsTheBudget() {
        assertTrue(CoordinationSchedule.fitting(new Coordinator(), 1000, 120).singleCycle());
        assertFalse(CoordinationSchedule.fitting(new Coordinator(), 1000, 4000).singleCycle());
    }

    @Test
    void aSecondStartDuringARoundIsRefused() {
        CoordinationSchedule s = new CoordinationSchedule(new Coordinator(), false);
        s.start(TEAM, Mode.ACTIVE, Memory.NONE);
        s.cycle();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> s.start(TEAM, Mode.ACTIVE, Memory.NONE));
        assertEquals("a coordination round is under way (1 of 6 phases done)", e.getMessage());
    }

    @Test
    void phasesOutOfOrderAreRefused() {
        var run = new Coordinator().start(TEAM, Mode.ACTIVE, Memory.NONE);
        IllegalStateException e = assertThrows(IllegalStateException.class, run::determineSubsets);
        assertEquals("phase 2 called after phase 0", e.getMessage());
    }
}

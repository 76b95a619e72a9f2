package phalanx.coordination;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.coordination.formation.Role;
import phalanx.coordination.formation.StretchedFormation;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.subsets.Subset;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

class CoordinatorTest {
    private final Coordinator coordinator = new Coordinator();

    @Test
    void everyPlayerGetsOneDistinctRoleAndOneOnBallPlayer() {
        TeamPlan plan = coordinator.coordinate(Scenarios.eleven(new Vector2(4, 2)), Mode.ACTIVE, Memory.NONE);
        assertEquals(11, plan.assignments().size());
        Set<Role> roles = EnumSet.noneOf(Role.class);
        int onBall = 0;
        for (Assignment a : plan.assignments()) {
            assertNotNull(a.role(), a.toString());
            assertTrue(roles.add(a.role()), "role given twice: " + a.role());
            assertNotNull(a.target());
            if (a.onBall()) onBall++;
        }
        assertEquals(EnumSet.allOf(Role.class), roles);
        assertEquals(1, onBall);
        assertEquals(Role.GK, plan.assignment(1).role());
        assertEquals(Action.GOALKEEPER, plan.assignment(1).action());
        // Ball at (4,2): the three nearest are 10 (-1,0) 5.39 m, 9 (-1,5) 5.83 m and 8 (-3,0) 7.28 m.
        assertEquals(List.of(10, 9, 8), plan.subsets().active());
        assertEquals(10, plan.onBall());
        assertEquals(new Vector2(4, 2), plan.assignment(10).target());
        assertFalse(plan.defensive());
        // Offence: the two other active players go to candidates ahead of the ball.
        for (int id : List.of(8, 9)) {
            assertEquals(Action.ACTIVE_POSITION, plan.assignment(id).action());
            assertTrue(plan.activeCandidates().contains(plan.assignment(id).target()));
            assertTrue(plan.assignment(id).target().x() > 4);
        }
        // Support players go to formation positions of their roles.
        for (Assignment a : plan.assignments())
            if (a.subset() == Subset.SUPPORT) assertEquals(plan.formation().position(a.role()), a.target());
        assertEquals(7L << 6, plan.supportEvaluated());   // 7 support players: 7·2^6
        assertTrue(plan.droppedRoles().isEmpty());
    }

    @Test
    void defensiveScenarioSendsActivePlayersBetweenBallAndGoal() {
        Vector2 ball = new Vector2(-8, -1);
        TeamPlan plan = coordinator.coordinate(Scenarios.eleven(ball), Mode.ACTIVE, Memory.NONE);
        assertTrue(plan.defensive());
        for (Assignment a : plan.assignments()) {
            if (a.action() == Action.ACTIVE_POSITION) {
                // The least-utility ring points: nearer our goal than the ball, never ahead of it.
                Vector2 goal = FieldSpec.V066.ownGoal();
                assertTrue(a.target().distanceTo(goal) < ball.distanceTo(goal), "defensive target not nearer our goal: " + a);
                assertTrue(a.target().x() <= ball.x() + 1e-9, "defensive target ahead of the ball: " + a);
                assertTrue(a.target().distanceTo(ball) <= 1.5 + 1e-9);
            }
        }
    }

    @Test
    void oneInactivePlayerDropsTheRoleFarthestFromTheBall() {
        Vector2 ball = new Vector2(6, -3);
        TeamBeliefs t = Scenarios.replace(Scenarios.eleven(ball), PlayerReport.lost(3));
        TeamPlan plan = coordinator.coordinate(t, Mode.ACTIVE, Memory.NONE);
        assertEquals(Action.LOCALIZE, plan.assignment(3).action());
        assertNull(plan.assignment(3).target());
        assertEquals(1, plan.droppedRoles().size());
        Role dropped = plan.droppedRoles().get(0);
        for (Role r : Role.forPlayers(11)) {
            if (r == Role.GK) continue;
            assertTrue(plan.formation().position(r).distanceTo(ball) <= plan.formation().position(dropped).distanceTo(ball) + 1e-9,
                    r + " is farther from the ball than the dropped " + dropped);
        }
        for (Assignment a : plan.assignments()) assertNotEquals(dropped, a.role());
    }

    @Test
    void previousOnBallPlayerKeepsTheBall() {
        // 10 at 1.0 m behind the ball, 9 at 1.6 m behind: 10 is nearer, but 9 had the ball.
        TeamBeliefs t = Scenarios.eleven(new Vector2(0, 0));
        t = Scenarios.replace(t, PlayerReport.complete(10, new Pose2(-1.0, 0, 0), Vector2.ZERO));
        t = Scenarios.replace(t, PlayerReport.complete(9, new Pose2(-1.6, 0.1, 0), Vector2.ZERO));
        TeamPlan first = coordinator.coordinate(t, Mode.ACTIVE, Memory.NONE);
        assertEquals(10, first.onBall());
        assertEquals(new Memory(10, Vector2.ZERO), first.memory());
        TeamPlan withNine = coordinator.coordinate(t, Mode.ACTIVE, new Memory(9, Vector2.ZERO));
        assertEquals(9, withNine.onBall());
        // 9 farther than the hysteresis (2.1 m against 1.0 m): the ball goes back to 10.
        TeamBeliefs far = Scenarios.replace(t, PlayerReport.complete(9, new Pose2(-2.1, 0.1, 0), Vector2.ZERO));
        assertEquals(10, coordinator.coordinate(far, Mode.ACTIVE, new Memory(9, Vector2.ZERO)).onBall());
    }

    @Test
    void nobodySeesTheBallSoThePreviousBallIsUsed() {
        TeamBeliefs t = new TeamBeliefs(FieldSpec.V066, List.of(PlayerReport.located(2, new Pose2(0, 0, 0))));
        assertEquals(new Vector2(3, 3), coordinator.coordinate(t, Mode.ACTIVE, new Memory(0, new Vector2(3, 3))).ball());
    }

    @Test
    void supportModeSendsEveryFieldPlayerToTheFormation() {
        TeamPlan plan = coordinator.coordinate(Scenarios.eleven(new Vector2(0, 0)), Mode.SUPPORT, Memory.NONE);
        assertEquals(0, plan.onBall());
        assertTrue(plan.subsets().active().isEmpty());
        assertEquals(10L << 9, plan.supportEvaluated());   // 10 support players: 5,120 mappings
        for (Assignment a : plan.assignments())
            if (a.id() != 1) assertEquals(Action.SUPPORT_POSITION, a.action());
    }

    @Test
    void waitModeTellsEveryFieldPlayerToWait() {
        TeamPlan plan = coordinator.coordinate(Scenarios.eleven(new Vector2(0, 0)), Mode.WAIT, Memory.NONE);
        for (Assignment a : plan.assignments())
            assertEquals(a.id() == 1 ? Action.GOALKEEPER : Action.WAIT, a.action());
    }

    @Test
    void nineAPlayerTeamOnTheOldField() {
        List<PlayerReport> r = new ArrayList<>();
        Vector2 ball = new Vector2(-3, 2);
        for (int i = 1; i <= 9; i++) r.add(PlayerReport.complete(i, new Pose2(-9 + i, i % 3 - 1, 0), ball));
        TeamPlan plan = coordinator.coordinate(new TeamBeliefs(FieldSpec.V065, r), Mode.ACTIVE, Memory.NONE);
        Set<Role> roles = EnumSet.noneOf(Role.class);
        for (Assignment a : plan.assignments()) roles.add(a.role());
        assertEquals(new HashSet<>(Role.forPlayers(9)), roles);
    }

    @Test
    void sevenT1sOnRcssservermjsFieldTakeTheStretchedFormationsSpots() {
        MjField mj = MjField.SSIM;
        StretchedFormation stretched = new StretchedFormation(mj, coordinator.config().formation());
        Coordinator onMj = new Coordinator(coordinator.config(), new DynamicProgrammingSupportMapper(), (ball, field) -> stretched.generate(ball));
        Vector2 ball = new Vector2(-12, 5);
        List<PlayerReport> r = new ArrayList<>();
        for (int i = 1; i <= 7; i++) r.add(PlayerReport.complete(i, new Pose2(-26 + 4 * i, 3 * (i % 3) - 3, 0), ball));
        TeamPlan plan = onMj.coordinate(new TeamBeliefs(mj.spec(), r), Mode.SUPPORT, Memory.NONE);
        assertEquals(stretched.generate(ball), plan.formation());
        Set<Role> roles = EnumSet.noneOf(Role.class);
        for (Assignment a : plan.assignments()) {
            roles.add(a.role());
            assertEquals(stretched.generate(ball).position(a.role()), a.target(), "player " + a.id() + " goes to its role's stretched spot");
        }
        assertEquals(new HashSet<>(Role.forPlayers(7)), roles, "the 7 roles, none dropped");
        assertTrue(plan.warnings().isEmpty(), "uniform numbers 1-7 on the 7-player field: " + plan.warnings());
    }

    @Test
    void garbageReportsStillGiveAPlanWithWarnings() {
        List<PlayerReport> r = new ArrayList<>();
        r.add(PlayerReport.complete(1, new Pose2(-14, 0, 0), new Vector2(Double.NaN, Double.NaN)));
        r.add(PlayerReport.ballOnly(2, Double.NaN, 0, 0));
        r.add(PlayerReport.located(3, new Pose2(Double.POSITIVE_INFINITY, 0, 0)));
        r.add(PlayerReport.located(40, new Pose2(0, 0, 0)));
        r.add(null);
        r.add(PlayerReport.located(4, new Pose2(2, 2, 0)));
        TeamPlan plan = coordinator.coordinate(new TeamBeliefs(FieldSpec.V066, r), Mode.ACTIVE, Memory.NONE);
        assertEquals(4, plan.assignments().size());
        assertEquals(Action.ON_BALL, plan.assignment(4).action());
        assertEquals(Action.LOCALIZE, plan.assignment(2).action());
        assertEquals(Action.LOCALIZE, plan.assignment(3).action());
        assertEquals(6, plan.warnings().size(), plan.warnings().toString());
    }

    @Test
    void emptyTeamGivesAnEmptyPlan() {
        TeamPlan plan = coordinator.coordinate(new TeamBeliefs(FieldSpec.V066, List.of()), Mode.ACTIVE, Memory.NONE);
        assertTrue(plan.assignments().isEmpty());
    }

    @Test
    void activePlayersWithoutCandidatesJoinSupport() {
        // Ball in their corner with a 3 m margin: no ring position survives, so only the on-ball player is active.
        CoordinationConfig c = CoordinationConfig.THESIS;
        CoordinationConfig wide = new CoordinationConfig(c.goalkeeperId(), c.activeCount(), c.ballClusterThreshold(),
                c.ballClusterExponent(), new CoordinationConfig.ActivePositionsConfig(1, 1.5, 12, 2, 12, 3, 24, 4.0, 9),
                c.onBall(), c.activeWeights(), c.collision(), c.supportWeights(), c.formation());
        TeamPlan plan = new Coordinator(wide, new phalanx.coordination.support.DynamicProgrammingSupportMapper())
                .coordinate(Scenarios.eleven(new Vector2(14, 9)), Mode.ACTIVE, Memory.NONE);
        assertTrue(plan.activeCandidates().isEmpty());
        assertEquals(1, plan.subsets().active().size());
        assertEquals(9, plan.subsets().support().size());
        assertEquals(10, plan.assignments().stream().filter(a -> a.role() != Role.GK).map(Assignment::role).distinct().count());
    }
}

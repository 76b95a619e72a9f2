package phalanx.coordination.beliefs;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

class BeliefsUpdateTest {
    private static final FieldSpec F = FieldSpec.V066;

    private static GlobalBeliefs update(Vector2 previous, PlayerReport... r) {
        return BeliefsUpdate.update(new TeamBeliefs(F, List.of(r)), 1.0, 3.0, previous);
    }

    @Test
    void typesCLBXGiveDistancesAsSection54Says() {
        GlobalBeliefs g = update(null,
                PlayerReport.complete(2, new Pose2(0, 0, 0), new Vector2(3, 4)),
                PlayerReport.located(3, new Pose2(3, 0, 90)),
                PlayerReport.ballOnly(4, 2.0, 0, Double.NaN),
                PlayerReport.ballOnly(5, 1.0, 90, 90),
                PlayerReport.lost(6));
        assertEquals(new Vector2(3, 4), g.ball());
        assertEquals(1, g.ballObservations());
        assertEquals(5, g.player(2).ballDistance(), 1e-12);
        assertEquals(4, g.player(3).ballDistance(), 1e-12);
        // B without heading: assumed facing +x, ball straight ahead 2 m: it stands 2 m behind the ball.
        assertEquals(1, g.player(4).position().x(), 1e-12);
        assertEquals(4, g.player(4).position().y(), 1e-12);
        assertEquals(2, g.player(4).ballDistance(), 1e-12);
        // B with heading 90 and bearing 90: the ball lies towards -x, so the player is 1 m to +x of it.
        assertEquals(4, g.player(5).position().x(), 1e-9);
        assertEquals(4, g.player(5).position().y(), 1e-9);
        assertNull(g.player(6).position());
        assertEquals(Double.POSITIVE_INFINITY, g.player(6).ballDistance());
        assertTrue(g.warnings().isEmpty(), g.warnings().toString());
    }

    @Test
    void fallenPlayersDoNotVoteOnTheBall() {
        GlobalBeliefs g = update(null,
                PlayerReport.complete(2, new Pose2(0, 0, 0), new Vector2(1, 1)),
                PlayerReport.complete(3, new Pose2(0, 0, 0), new Vector2(5, 5)).asFallen());
        assertEquals(new Vector2(1, 1), g.ball());
        assertFalse(g.player(3).usable());
    }

    @Test
    void noBallFallsBackToTheCoordinatorThenThePreviousBallThenTheCentre() {
        TeamBeliefs withFallback = new TeamBeliefs(F, List.of(PlayerReport.lost(2)), new Vector2(2, 2));
        assertEquals(new Vector2(2, 2), BeliefsUpdate.update(withFallback, 1, 3, new Vector2(7, 7)).ball());
        assertEquals(new Vector2(7, 7), update(new Vector2(7, 7), PlayerReport.lost(2)).ball());
        GlobalBeliefs none = update(null, PlayerReport.lost(2));
        assertEquals(Vector2.ZERO, none.ball());
        assertTrue(none.warnings().get(0).contains("nobody knows where the ball is"), none.warnings().toString());
    }

    @Test
    void uniformNumberOutOfRangeIsDroppedWithAMessage() {
        GlobalBeliefs g = update(null, PlayerReport.located(12, new Pose2(0, 0, 0)), PlayerReport.located(0, new Pose2(0, 0, 0)));
        assertTrue(g.players().isEmpty());
        assertEquals("report from player 12 dropped: uniform numbers are 1..11", g.warnings().get(0));
        assertEquals("report from player 0 dropped: uniform numbers are 1..11", g.warnings().get(1));
    }

    @Test
    void duplicateReportKeepsTheLaterOne() {
        GlobalBeliefs g = update(null, PlayerReport.located(4, new Pose2(0, 0, 0)), PlayerReport.located(4, new Pose2(1, 0, 0)));
        assertEquals(1, g.players().size());
        assertEquals(1, g.player(4).position().x());
        assertEquals("player 4 reported twice: the later report is used", g.warnings().get(0));
    }

    @Test
    void typeCWithoutFiniteBallBecomesL() {
        GlobalBeliefs g = update(null, PlayerReport.complete(4, new Pose2(1, 2, 0), new Vector2(Double.NaN, 0)));
        assertEquals(ReportType.L, g.player(4).type());
        assertEquals("player 4 sent type C without a finite ball: used as type L", g.warnings().get(0));
    }

    @Test
    void typeCWithoutFinitePositionBecomesX() {
        GlobalBeliefs g = update(null, PlayerReport.complete(4, new Pose2(Double.NaN, 2, 0), new Vector2(1, 1)));
        assertEquals(ReportType.X, g.player(4).type());
        assertEquals("player 4 sent type C without a finite position: used as type X", g.warnings().get(0));
        // Its ball was not used either.
        assertEquals(0, g.ballObservations());
    }

    @Test
    void typeLWithoutPositionBecomesX() {
        GlobalBeliefs g = update(null, new PlayerReport(5, ReportType.L, null, null, Double.NaN, Double.NaN, Double.NaN, false));
        assertEquals(ReportType.X, g.player(5).type());
        assertEquals("player 5 sent type L without a finite position: used as type X", g.warnings().get(0));
    }

    @Test
    void typeBWithNegativeDistanceBecomesX() {
        GlobalBeliefs g = update(null, PlayerReport.ballOnly(6, -1, 0, 0));
        assertEquals(ReportType.X, g.player(6).type());
        assertEquals("player 6 sent type B with distance -1.0 and bearing 0.0: used as type X", g.warnings().get(0));
    }

    @Test
    void ballFarOutsideTheFieldIsIgnored() {
        GlobalBeliefs g = update(null, PlayerReport.complete(7, new Pose2(0, 0, 0), new Vector2(40, 0)));
        assertEquals(ReportType.L, g.player(7).type());
        assertEquals("player 7 sees the ball at (40.00, 0.00), more than 3.0 m outside the field: ball ignored",
                g.warnings().get(0));
    }

    @Test
    void nullReportIsDropped() {
        java.util.List<PlayerReport> list = new java.util.ArrayList<>();
        list.add(null);
        GlobalBeliefs g = BeliefsUpdate.update(new TeamBeliefs(F, list), 1, 3, null);
        assertEquals("null report dropped", g.warnings().get(0));
    }
}

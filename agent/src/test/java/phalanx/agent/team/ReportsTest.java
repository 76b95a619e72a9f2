package phalanx.agent.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Side;
import phalanx.comm.team.TeamMessage;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.fall.FallState;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class ReportsTest {
    private static WorldBelief belief(double ballAge, boolean heard, FallState fall) {
        Pose2 self = new Pose2(-4, 1, 30);
        Vector2 ball = new Vector2(-1, 2);
        return new WorldBelief(10, Side.LEFT, 6, self, 0.9, 0.1, self.toRelative(ball), ball, ballAge, null,
                List.of(), List.of(), fall, heard);
    }

    @Test
    void aSeenBallIsReportedCompleteAndAHeardOneIsNot() {
        var seen = (TeamMessage.Complete) Reports.of(6, belief(0.2, false, FallState.STANDING));
        assertEquals(-1, seen.ballX(), 1e-9);
        assertEquals(2, seen.ballY(), 1e-9);
        // The same ball from teammates' reports: sent back it would count twice in the coordinator's fusion.
        var heard = Reports.of(6, belief(0.2, true, FallState.STANDING));
        assertInstanceOf(TeamMessage.Location.class, heard);
        assertEquals(-4, ((TeamMessage.Location) heard).x(), 1e-9);
        assertInstanceOf(TeamMessage.Location.class, Reports.of(6, belief(Reports.BALL_FRESH_S + 0.1, false, FallState.STANDING)));
        assertEquals(new TeamMessage.Unaware(6, true), Reports.of(6, belief(0.2, false, FallState.FALLEN_BACK)));
    }
}

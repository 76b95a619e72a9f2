package phalanx.agent.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.comm.team.TeamMessage;
import phalanx.comm.team.round.RoundReports;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.Coordinator;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.model.field.FieldSpec;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import static org.junit.jupiter.api.Assertions.*;

/** The goalkeeper's rounds: orders from reports, and the log line a match review reads when On Ball moves. */
class RoundPlannerTest {
    private static RoundReports round(int n, TeamMessage.Report... r) {
        Map<Integer, TeamMessage.Report> m = new java.util.TreeMap<>();
        for (TeamMessage.Report x : r) m.put(x.sender(), x);
        return new RoundReports(n, n * 10L, m, Set.of());
    }

    private static RoundReports round(int n, Set<Integer> inactive, TeamMessage.Report... r) {
        Map<Integer, TeamMessage.Report> m = new java.util.TreeMap<>();
        for (TeamMessage.Report x : r) m.put(x.sender(), x);
        return new RoundReports(n, n * 10L, m, inactive);
    }

    private static RoundPlanner planner() {
        return new RoundPlanner(new Coordinator(CoordinationConfig.THESIS, new DynamicProgrammingSupportMapper()),
                FieldSpec.V066, 1, () -> null, () -> PlayMode.PLAY_ON, () -> false);
    }

    @Test
    void aPlayerNotHeardForOneRoundKeepsItsLastReport() {
        RoundPlanner p = planner();
        TeamMessage.Report atBall = new TeamMessage.Complete(2, 1.7, 0, 0, 2, 0);
        TeamMessage.Report far = new TeamMessage.Complete(3, -8, 3, 0, 2, 0);
        assertTrue(p.actions(round(1, Set.of(), atBall, far)).contains(Action.of(2, ActionId.ON_BALL)));
        // Round 2: player 2's report is lost on the channel; its round-1 report stands in, so it stays On Ball
        // (and is ordered), instead of On Ball going to player 3, 10 m away.
        List<Action> second = p.actions(round(2, Set.of(), far));
        assertTrue(second.contains(Action.of(2, ActionId.ON_BALL)), second.toString());
        assertFalse(second.contains(Action.of(3, ActionId.ON_BALL)), second.toString());
        // Round 3: missing again, the channel counts it inactive; its old report is not used any more.
        List<Action> third = p.actions(round(3, Set.of(2), far));
        assertTrue(third.contains(Action.of(3, ActionId.ON_BALL)), third.toString());
        assertTrue(third.stream().noneMatch(a -> a.recipient() == 2), third.toString());
    }

    @Test
    void aReportOlderThanThePreviousRoundIsNotUsed() {
        RoundPlanner p = planner();
        TeamMessage.Report far = new TeamMessage.Complete(3, -8, 3, 0, 2, 0);
        p.actions(round(1, Set.of(), new TeamMessage.Complete(2, 1.7, 0, 0, 2, 0), far));
        // Round 2 was aborted (a play-mode change): the planner next sees round 3, without player 2.
        List<Action> third = p.actions(round(3, Set.of(), far));
        assertTrue(third.contains(Action.of(3, ActionId.ON_BALL)), third.toString());
        assertTrue(third.stream().noneMatch(a -> a.recipient() == 2), third.toString());
    }

    @Test
    void ordersTheNearestOnBallAndLogsWhenOnBallMoves() {
        RoundPlanner p = new RoundPlanner(new Coordinator(CoordinationConfig.THESIS, new DynamicProgrammingSupportMapper()),
                FieldSpec.V066, 1, () -> null, () -> PlayMode.PLAY_ON, () -> false);
        List<String> lines = new ArrayList<>();
        Handler h = new Handler() {
            @Override public void publish(LogRecord r) { lines.add(r.getMessage()); }
            @Override public void flush() {}
            @Override public void close() {}
        };
        Logger log = Logger.getLogger(RoundPlanner.class.getName());
        log.addHandler(h);
        java.util.logging.Level level = log.getLevel();
        log.setLevel(java.util.logging.Level.INFO);
        try {
            // Player 2 stands 0.3 m behind the ball at (2, 0), player 3 4 m away: 2 goes On Ball.
            List<Action> first = p.actions(round(1, new TeamMessage.Complete(2, 1.7, 0, 0, 2, 0),
                    new TeamMessage.Complete(3, -2, 1, 0, 2, 0)));
            assertTrue(first.contains(Action.of(2, ActionId.ON_BALL)), first + " " + lines);
            assertTrue(lines.stream().anyMatch(l -> l.startsWith("round 1: On Ball 0 -> 2, ball (2.00,0.00);")), lines.toString());
            // The ball rolls to player 3: On Ball moves, and the line gives both players' beliefs.
            lines.clear();
            List<Action> second = p.actions(round(2, new TeamMessage.Complete(2, 1.7, 0, 0, -1.8, 1),
                    new TeamMessage.Complete(3, -2, 1, 0, -1.8, 1)));
            assertTrue(second.contains(Action.of(3, ActionId.ON_BALL)), second.toString());
            assertEquals(1, lines.size(), lines.toString());
            String l = lines.get(0);
            assertTrue(l.startsWith("round 2: On Ball 2 -> 3, ball (-1.80,1.00);"), l);
            assertTrue(l.contains(" 3:C (-2.00,1.00) d=0.20") && l.contains(" 2:C (1.70,0.00) d=3.64"), l);
            // Nothing new when On Ball stays.
            lines.clear();
            p.actions(round(3, new TeamMessage.Complete(2, 1.7, 0, 0, -1.8, 1), new TeamMessage.Complete(3, -2, 1, 0, -1.8, 1)));
            assertTrue(lines.stream().noneMatch(x -> x.contains("On Ball")), lines.toString());
        } finally {
            log.removeHandler(h);
            log.setLevel(level);
        }
    }
}

package phalanx.comm.team.round;

import phalanx.comm.team.ActionId;
import phalanx.comm.team.Action;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessageCodec;
import phalanx.comm.team.TeamMessage;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Supplier;

import static org.junit.jupiter.api.Assertions.*;

class FieldPlayerRoundsTest {
    static final TeamKey KEY = CoordinatorRoundsTest.KEY;
    static final String TEAM = CoordinatorRoundsTest.TEAM;
    final TeamMessageCodec ours = new TeamMessageCodec(KEY, ChannelConfig.DEFAULT);
    final List<Long> asked = new ArrayList<>();

    Supplier<TeamMessage.Report> report(long cycle, TeamMessage.Report r) {
        return () -> {
            asked.add(cycle);
            return r;
        };
    }

    /** Steps the player through [from, to], hearing {@code script.get(cycle)}; returns what it said, by cycle. */
    Map<Long, String> run(FieldPlayerRounds p, long from, long to, Map<Long, List<Hear>> script, List<ChannelEvent> events) {
        Map<Long, String> said = new TreeMap<>();
        for (long c = from; c <= to; c++) {
            ChannelOutput out = p.step(c, PlayMode.PLAY_ON, script.getOrDefault(c, List.of()),
                    report(c, new TeamMessage.Location(p.unum(), 1.5, -2.5, 30)));
            if (out.say() != null) said.put(c, out.say());
            events.addAll(out.events());
        }
        return said;
    }

    Hear fromCoordinator(TeamMessage m, long said) {
        return new Hear(TEAM, 0, false, 170, ours.encode(m, said));
    }

    @Test
    void announcesItselfInItsLabelledSlotUntilTheCoordinatorSpeaks() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        Map<Long, String> said = run(p, 0, 50, Map.of(), ev);
        assertEquals(List.of(6L, 28L, 50L), List.copyOf(said.keySet())); // label 4 = slot 3, every 11 slots
        assertEquals(new TeamMessage.Init(4), ours.decode(said.get(6L), 8).message());
        assertEquals(FieldPlayerRounds.Mode.AUTONOMOUS, p.mode());
        assertTrue(asked.isEmpty());
    }

    /** Every teammate's report is heard by all: a field player passes them on (their ball is its fall-back, issue 19). */
    @Test
    void aTeammatesReportIsPassedOnAndItsOwnIsNot() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        TeamMessage.Complete mate = new TeamMessage.Complete(7, -3.0, 1.0, 45, 2.0, -1.0);
        run(p, 0, 12, Map.of(10L, List.of(new Hear(TEAM, 0, false, 30, ours.encode(mate, 8)))), ev);
        assertEquals(1, ev.size(), ev.toString());
        var heard = (ChannelEvent.ReportHeard) ev.get(0);
        assertEquals(8, heard.saidCycle());
        assertEquals(10, heard.cycle());
        var c = (TeamMessage.Complete) heard.report();
        assertEquals(7, c.sender());
        assertEquals(2.0, c.ballX(), 0.021);
        assertEquals(-1.0, c.ballY(), 0.021);
        // A foreign team's text and the player's own number are not passed on.
        ev.clear();
        run(p, 13, 20, Map.of(14L, List.of(new Hear("Them", 0, false, 30, ours.encode(mate, 12))),
                16L, List.of(new Hear(TEAM, 0, false, 30, ours.encode(new TeamMessage.Location(4, 1, 1, 0), 14)))), ev);
        assertTrue(ev.stream().noneMatch(e -> e instanceof ChannelEvent.ReportHeard), ev.toString());
    }

    @Test
    void reportsInItsSlotAfterStartThenTakesItsActionAndKnowsTheNextRound() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        // "s" said at 22, heard at 24: reports from 24 on, player 4 in the third slot, at 28
        Map<Long, String> said = run(p, 0, 40, Map.of(24L, List.of(fromCoordinator(new TeamMessage.Start(1), 22))), ev);
        assertEquals(List.of(6L, 28L), List.copyOf(said.keySet()));
        assertEquals(List.of(28L), asked);
        var r = (TeamMessage.Location) ours.decode(said.get(28L), 30).message();
        assertEquals(1.5, r.x(), 0.021);
        assertEquals(List.of(new ChannelEvent.Coordinated(24)), ev);
        assertEquals(FieldPlayerRounds.Mode.COORDINATED, p.mode());

        // an action message said at 44 with 2 more to come: player 4's action is in it
        Action mine = Action.walkTo(4, -8.0, 2.0, 90);
        TeamMessage.Actions a = new TeamMessage.Actions(2, List.of(Action.walkTo(3, -9, -2, 0), mine));
        ev.clear();
        said = run(p, 41, 80, Map.of(46L, List.of(fromCoordinator(a, 44))), ev);
        assertEquals(1, ev.size());
        Action got = ((ChannelEvent.ActionReceived) ev.get(0)).action();
        assertEquals(mine.id(), got.id());
        assertEquals(-8.0, got.x(), 0.021);
        assertEquals(got, p.currentAction());
        // next round: 44 + 3 slots (this and two more messages) + 10 slots of pause = 70, player 4 at 74
        assertEquals(List.of(74L), List.copyOf(said.keySet()));
    }

    @Test
    void endAlsoSchedulesTheNextRound() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 2, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        Map<Long, String> said = run(p, 30, 80, Map.of(46L, List.of(fromCoordinator(new TeamMessage.End(1), 44))), ev);
        assertEquals(List.of(66L), List.copyOf(said.keySet())); // 44 + 1 slot + 10 slots, first report slot
    }

    @Test
    void ignoresReplayedOtherTeamsAndForgedActions() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        TeamMessage.Actions a = new TeamMessage.Actions(0, List.of(Action.of(4, ActionId.STAND_UP)));
        TeamMessageCodec guess = new TeamMessageCodec(TeamKey.fromSecret("someone-elses-key-000"), ChannelConfig.DEFAULT);
        run(p, 40, 60, Map.of(
                50L, List.of(new Hear(null, 0, false, 10, ours.encode(a, 44))),    // replayed: said 44, heard 50
                52L, List.of(new Hear("Rival", 0, false, 10, ours.encode(a, 50))), // labelled as the opponents'
                54L, List.of(new Hear(TEAM, 0, false, 10, guess.encode(a, 52))),   // wrong key
                56L, List.of(new Hear(TEAM, 0, true, 0, ours.encode(a, 54)))),     // its own (cannot be, but skipped)
                ev);
        assertTrue(ev.isEmpty(), ev.toString());
        assertNull(p.currentAction());
        assertEquals(1, p.rejected(Rejection.FOREIGN_TEAM));
        assertEquals(2, p.rejected(Rejection.BAD_CHECK) + p.rejected(Rejection.WRONG_TIME));
    }

    @Test
    void fallsBackToItsOwnBeliefsWhenTheCoordinatorGoesQuiet() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        TeamMessage.Actions a = new TeamMessage.Actions(0, List.of(Action.of(4, ActionId.ON_BALL)));
        Map<Long, String> said = run(p, 40, 200, Map.of(46L, List.of(fromCoordinator(a, 44))), ev);
        // silence limit 100 cycles after the last word (46): at 147 it acts alone
        assertEquals(ChannelEvent.CoordinatorSilent.class, ev.get(ev.size() - 1).getClass());
        assertEquals(147, ev.get(ev.size() - 1).cycle());
        assertNull(p.currentAction());
        assertEquals(FieldPlayerRounds.Mode.AUTONOMOUS, p.mode());
        // its report at 44 + 2 + 20 + 4 = 70; after the fallback it announces itself in its slots again
        assertEquals(70L, said.keySet().iterator().next());
        List<Long> after = said.keySet().stream().filter(c -> c > 147).toList();
        assertEquals(List.of(160L, 182L), after); // label 4's slots: 6 + 22k
        assertEquals(new TeamMessage.Init(4), ours.decode(said.get(160L), 162).message());
    }

    @Test
    void staysQuietWhileItHearsARoundGoingOn() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, KEY, TEAM);
        List<ChannelEvent> ev = new ArrayList<>();
        // other players' reports every slot: a round it has not been told about
        Map<Long, List<Hear>> script = new java.util.HashMap<>();
        for (long c = 2; c <= 40; c += 2) script.put(c, List.of(new Hear(TEAM, 0, false, 5, ours.encode(new TeamMessage.Unaware(7, false), c - 2))));
        Map<Long, String> said = run(p, 0, 40, script, ev);
        assertTrue(said.isEmpty(), said.toString());
    }

    @Test
    void anUnsendableReportGoesOutAsUnaware() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 3, KEY, TEAM);
        p.step(24, PlayMode.PLAY_ON, List.of(fromCoordinator(new TeamMessage.Start(1), 22)), null);
        p.step(25, PlayMode.PLAY_ON, List.of(), null);
        ChannelOutput out = p.step(26, PlayMode.PLAY_ON, List.of(), () -> new TeamMessage.Location(3, Double.NaN, 0, 0));
        assertEquals(new TeamMessage.Unaware(3, false), ours.decode(out.say(), 28).message());
        assertThrows(IllegalArgumentException.class, () -> new FieldPlayerRounds(ChannelConfig.DEFAULT, 1, KEY, TEAM));
        assertThrows(IllegalArgumentException.class, () -> new FieldPlayerRounds(ChannelConfig.DEFAULT, 12, KEY, TEAM));
    }

    @Test
    void aPlayModeChangeVoidsTheSchedule() {
        FieldPlayerRounds p = new FieldPlayerRounds(ChannelConfig.DEFAULT, 5, KEY, TEAM);
        p.step(24, PlayMode.PLAY_ON, List.of(fromCoordinator(new TeamMessage.Start(1), 22)), null);
        p.step(25, PlayMode.PLAY_ON, List.of(), null);
        // player 5's slot would be 22 + 2 + 3 x 2 = 30, but the play mode changes at 26 and the
        // coordinator says "s" then: heard at 28, player 5 reports at 26 + 2 + 3 x 2 = 34
        List<Long> said = new ArrayList<>();
        for (long c = 26; c <= 40; c++) {
            List<Hear> h = c == 28 ? List.of(fromCoordinator(new TeamMessage.Start(1), 26)) : List.of();
            if (p.step(c, PlayMode.KICK_IN_LEFT, h, null).say() != null) said.add(c);
        }
        assertEquals(List.of(34L), said);
    }
}

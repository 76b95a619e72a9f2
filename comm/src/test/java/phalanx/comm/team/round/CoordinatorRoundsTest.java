package phalanx.comm.team.round;

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
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

import static org.junit.jupiter.api.Assertions.*;

class CoordinatorRoundsTest {
    static final TeamKey KEY = TeamKey.fromSecret("coordinator-test-key-42");
    static final String TEAM = "Phalanx";
    final TeamMessageCodec ours = new TeamMessageCodec(KEY, ChannelConfig.DEFAULT);

    /** Heard from a team-mate in cycle {@code said + 2}. */
    Hear heard(TeamMessage m, long said) {
        return new Hear(TEAM, 0, false, 45, ours.encode(m, said));
    }

    static TeamMessage.Report reportOf(int u) {
        return new TeamMessage.Complete(u, -u, u / 2.0, 5 * u, -3, 1);
    }

    /** Drives the coordinator from {@code from} to {@code to} with what {@code hears} gives each cycle. */
    static Map<Long, ChannelOutput> run(CoordinatorRounds c, long from, long to, Function<Long, List<Hear>> hears) {
        Map<Long, ChannelOutput> out = new HashMap<>();
        for (long cycle = from; cycle <= to; cycle++) out.put(cycle, c.step(cycle, PlayMode.PLAY_ON, hears.apply(cycle)));
        return out;
    }

    /** Every player says "i" in its labelled slot: u at 2(u-1), heard 2 cycles later. */
    List<Hear> inits(long cycle) {
        if (cycle % 2 != 0 || cycle < 4 || cycle > 22) return List.of();
        return List.of(heard(new TeamMessage.Init((int) (cycle / 2)), cycle - 2));
    }

    /** Reports of these players in their slots of a round whose first report slot is {@code first}. */
    List<Hear> reports(long cycle, long first, List<Integer> who) {
        long said = cycle - 2;
        if ((said - first) % 2 != 0) return List.of();
        int u = (int) ((said - first) / 2) + 2;
        return who.contains(u) ? List.of(heard(reportOf(u), said)) : List.of();
    }

    static List<Integer> range(int from, int to) {
        List<Integer> l = new ArrayList<>();
        for (int u = from; u <= to; u++) l.add(u);
        return l;
    }

    static <T> List<T> events(Map<Long, ChannelOutput> out, Class<T> type) {
        List<T> l = new ArrayList<>();
        out.keySet().stream().sorted().forEach(c -> out.get(c).events().stream().filter(type::isInstance).map(type::cast).forEach(l::add));
        return l;
    }

    final List<RoundReports> calls = new ArrayList<>();
    final CoordinationProcedure walkHome = r -> {
        calls.add(r);
        List<Action> a = new ArrayList<>();
        for (int u : r.reports().keySet()) a.add(Action.walkTo(u, -u, 1, 0));
        return a;
    };

    @Test
    void saysStartInItsOwnSlotOnceEveryPlayerHasAnnouncedItself() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        Map<Long, ChannelOutput> out = run(c, 0, 22, this::inits);
        for (long cycle = 0; cycle < 22; cycle++) assertNull(out.get(cycle).say(), "quiet at " + cycle);
        // player 11's "i" (said at 20) arrives at 22: slot 11, label 1 again, the coordinator's
        var start = ours.decode(out.get(22L).say(), 24);
        assertEquals(new TeamMessage.Start(1), start.message());
        assertEquals(22, start.saidCycle());
        assertEquals(range(2, 11), events(out, ChannelEvent.PlayerJoined.class).stream().map(ChannelEvent.PlayerJoined::unum).toList());
        assertEquals(List.of(new ChannelEvent.RoundStarted(1, 22)), events(out, ChannelEvent.RoundStarted.class));
        assertEquals(CoordinatorRounds.Phase.REPORTS, c.phase());
    }

    @Test
    void gathersTheReportsThenDispatchesPackedActionsThenPausesAndStartsTheNextRound() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        run(c, 0, 22, this::inits);
        // reports: player u says at 24 + 2(u-2); player 11 at 42, heard at 44
        Map<Long, ChannelOutput> out = run(c, 23, 80, cy -> reports(cy, 24, range(2, 11)));
        assertEquals(List.of(new ChannelEvent.ReportsComplete(1, 44, 10, List.of())), events(out, ChannelEvent.ReportsComplete.class));
        assertEquals(1, calls.size());
        assertEquals(10, calls.get(0).reports().size());
        var five = (TeamMessage.Complete) calls.get(0).reports().get(5);
        assertEquals(-5, five.x(), 0.02);
        assertEquals(25, five.thetaDeg(), 0.71);
        // 10 walk-to-coordinate actions: two a message, five messages, one slot apart from cycle 44
        List<Action> sent = new ArrayList<>();
        for (long cycle = 44; cycle <= 52; cycle += 2) {
            var d = ours.decode(out.get(cycle).say(), cycle + 2);
            var a = (TeamMessage.Actions) d.message();
            assertEquals((52 - cycle) / 2, a.remaining());
            sent.addAll(a.actions());
            assertNull(out.get(cycle + 1).say());
        }
        assertEquals(range(2, 11), sent.stream().map(Action::recipient).sorted().toList());
        assertEquals(List.of(new ChannelEvent.ActionsDispatched(1, 52, 5, 10)), events(out, ChannelEvent.ActionsDispatched.class));
        // pause: 20 cycles after the slot of the last action message, no "s"
        assertEquals(List.of(new ChannelEvent.RoundStarted(2, 74)), events(out, ChannelEvent.RoundStarted.class));
        for (long cycle = 53; cycle <= 80; cycle++) assertNull(out.get(cycle).say());
    }

    @Test
    void aMissingReportIsWaitedForOneCycleThenThePlayerTurnsInactiveAndBackActive() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        run(c, 0, 22, this::inits);
        List<Integer> without11 = range(2, 10);
        Map<Long, ChannelOutput> r1 = run(c, 23, 75, cy -> reports(cy, 24, without11));
        // last report slot 42: heard at 44 at the earliest, 45 at the latest
        assertEquals(List.of(new ChannelEvent.ReportsComplete(1, 45, 9, List.of(11))), events(r1, ChannelEvent.ReportsComplete.class));
        // 9 actions in 5 messages said at 45, 47, ..., 53; round 2 starts a slot and the pause later: 75
        assertEquals(List.of(new ChannelEvent.RoundStarted(2, 75)), events(r1, ChannelEvent.RoundStarted.class));
        Map<Long, ChannelOutput> r2 = run(c, 76, 127, cy -> reports(cy, 75, without11));
        assertEquals(List.of(new ChannelEvent.PlayerInactive(11, 96)), events(r2, ChannelEvent.PlayerInactive.class));
        assertTrue(calls.get(1).inactive().contains(11));
        long first3 = events(r2, ChannelEvent.RoundStarted.class).get(0).cycle();
        assertEquals(126, first3); // 9 action messages at 96-104, then a slot and the pause
        // round 3: player 11 is inactive, so the round closes as soon as its slot is over
        Map<Long, ChannelOutput> r3 = run(c, 128, first3 + 25, cy -> reports(cy, first3, without11));
        var complete = events(r3, ChannelEvent.ReportsComplete.class).get(0);
        assertEquals(first3 + 20, complete.cycle());
        assertEquals(List.of(11), complete.missing());
        // player 11 is back in round 4
        // 9 action messages at first3 + 20 ... + 28, then a slot and the pause
        long start4 = first3 + 50;
        Map<Long, ChannelOutput> gap = run(c, first3 + 26, start4, cy -> List.of());
        assertEquals(List.of(new ChannelEvent.RoundStarted(4, start4)), events(gap, ChannelEvent.RoundStarted.class));
        Map<Long, ChannelOutput> r4 = run(c, start4 + 1, start4 + 25, cy -> reports(cy, start4, range(2, 11)));
        assertEquals(List.of(new ChannelEvent.PlayerJoined(11, start4 + 20)), events(r4, ChannelEvent.PlayerJoined.class));
        assertEquals(10, events(r4, ChannelEvent.ReportsComplete.class).get(0).heard());
    }

    @Test
    void replayedForeignAndSpoofedReportsDoNotCount() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        run(c, 0, 22, this::inits);
        TeamMessageCodec guess = new TeamMessageCodec(TeamKey.fromSecret("not-the-team-key-at-all"), ChannelConfig.DEFAULT);
        Map<Long, ChannelOutput> out = run(c, 23, 46, cy -> {
            List<Hear> h = new ArrayList<>(reports(cy, 24, List.of(2, 3, 4, 6, 7, 8, 9, 10, 11)));
            if (cy == 30) {
                // player 5's slot is 30 (said): an opponent says a copy of player 4's report heard at 30
                h.add(new Hear(null, 0, false, 10, ours.encode(reportOf(5), 28)));
                // the server labels it with the opponents' name: dropped unchecked
                h.add(new Hear("Rival", 0, false, 10, ours.encode(reportOf(5), 28)));
                // forged with a guessed key
                h.add(new Hear(TEAM, 0, false, 10, guess.encode(reportOf(5), 28)));
            }
            return h;
        });
        assertEquals(List.of(5), events(out, ChannelEvent.ReportsComplete.class).get(0).missing());
        assertEquals(1, c.rejected(Rejection.FOREIGN_TEAM));
        assertEquals(1, c.rejected(Rejection.BAD_CHECK));
        // said at 28 and heard at 30 is in time, but for slot 28 (player 4's), not player 5's
        assertFalse(calls.get(0).reports().containsKey(5));
    }

    @Test
    void aReplayHeardFourCyclesLateIsRejected() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        run(c, 0, 22, this::inits);
        // player 2's real report (said 24) is lost; an opponent replays it at 26 and we hear it at 28
        Map<Long, ChannelOutput> out = run(c, 23, 46, cy -> {
            List<Hear> h = new ArrayList<>(reports(cy, 24, range(3, 11)));
            if (cy == 28) h.add(new Hear(null, 0, false, 10, ours.encode(reportOf(2), 24)));
            return h;
        });
        assertEquals(List.of(2), events(out, ChannelEvent.ReportsComplete.class).get(0).missing());
        assertEquals(1, c.rejected(Rejection.WRONG_TIME) + c.rejected(Rejection.BAD_CHECK));
    }

    @Test
    void aPlayModeChangeDropsTheRoundAndStartsANewOneAtOnce() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        run(c, 0, 22, this::inits);
        run(c, 23, 30, cy -> reports(cy, 24, range(2, 11)));
        ChannelOutput out = c.step(31, PlayMode.KICK_IN_LEFT, List.of());
        assertEquals(List.of(new ChannelEvent.RoundAborted(1, 31), new ChannelEvent.RoundStarted(2, 31)), out.events());
        assertEquals(new TeamMessage.Start(1), ours.decode(out.say(), 33).message());
    }

    @Test
    void withoutAllInitsTheFirstRoundStartsAfterTheTimeout() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, walkHome);
        Map<Long, ChannelOutput> out = run(c, 0, 120, cy -> cy <= 10 ? inits(cy) : List.of());
        // timeout 100 cycles; the coordinator's slots are every 22 cycles: 0, 22, ..., 110
        List<Long> says = out.keySet().stream().filter(k -> out.get(k).say() != null).sorted().toList();
        assertEquals(List.of(110L), says);
        assertEquals(range(2, 5), events(out, ChannelEvent.PlayerJoined.class).stream().map(ChannelEvent.PlayerJoined::unum).toList());
    }

    @Test
    void aFailingProcedureClosesTheRoundWithEnd() {
        CoordinatorRounds c = new CoordinatorRounds(ChannelConfig.DEFAULT, KEY, TEAM, r -> {
            throw new IllegalStateException("no formation for this");
        });
        run(c, 0, 22, this::inits);
        Map<Long, ChannelOutput> out = run(c, 23, 70, cy -> reports(cy, 24, range(2, 11)));
        assertEquals(new TeamMessage.End(1), ours.decode(out.get(44L).say(), 46).message());
        assertEquals(List.of(new ChannelEvent.ActionsDispatched(1, 44, 1, 0)), events(out, ChannelEvent.ActionsDispatched.class));
        assertEquals(List.of(new ChannelEvent.RoundStarted(2, 66)), events(out, ChannelEvent.RoundStarted.class));
    }
}

package phalanx.comm.team.round;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.MjTeamMessageCodec;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessage;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The unchanged round state machines on rcssservermj's terms ({@link ChannelConfig#MJ}: 7 players, 1-cycle slots;
 * {@link MjTeamMessageCodec#text()}): an air as rcsssmj 0.2.1 makes it (docs/rcssservermj.md, "Say and hear"):
 * a say in the reply to perception c is heard by everyone else in perception c + 2, never by its speaker, and with
 * at most three speakers a cycle every message is heard.
 */
class MjRoundsTest {
    private static final TeamKey KEY = TeamKey.fromSecret("mj-rounds-test-key-0001");
    private static final ChannelConfig MJ = ChannelConfig.MJ;
    /** The kick-off, a play-mode change: the coordinator starts a round with "s" at once. */
    private static final long KICK_OFF = 300;

    private final List<RoundReports> rounds = new ArrayList<>();
    /** Player 7 to the ball, the others to a spot each: six actions, five frames (one pose and one bare action a frame). */
    private final CoordinationProcedure plan = r -> {
        rounds.add(r);
        List<Action> a = new ArrayList<>();
        for (int u = 2; u <= 7; u++) a.add(u == 7 ? Action.of(u, ActionId.ON_BALL) : Action.walkTo(u, -20 + u, 3 * u - 12, 0));
        return a;
    };

    @Test
    void everyRoundHearsAllSixReportsAndEveryFieldPlayerItsOrder() {
        var coordinator = new CoordinatorRounds(MJ, new MjTeamMessageCodec(KEY, MJ).text(), null, plan);
        List<FieldPlayerRounds> players = new ArrayList<>();
        for (int u = 2; u <= 7; u++) players.add(new FieldPlayerRounds(MJ, u, new MjTeamMessageCodec(KEY, MJ).text(), null));
        Map<Long, List<Said>> air = new TreeMap<>();   // heard in cycle c: said in c - 2
        Map<Long, List<Integer>> speakers = new TreeMap<>();
        List<ChannelEvent.ReportsComplete> closed = new ArrayList<>();
        int[] received = new int[8];
        for (long c = 0; c < 600; c++) {
            PlayMode mode = c < KICK_OFF ? PlayMode.BEFORE_KICK_OFF : PlayMode.KICK_OFF_LEFT;
            List<Said> now = air.getOrDefault(c, List.of());
            List<Said> said = new ArrayList<>();
            ChannelOutput out = coordinator.step(c, mode, heardBy(1, now));
            for (ChannelEvent e : out.events()) if (e instanceof ChannelEvent.ReportsComplete r) closed.add(r);
            if (out.say() != null) said.add(new Said(1, out.say()));
            for (FieldPlayerRounds p : players) {
                int u = p.unum();
                out = p.step(c, mode, heardBy(u, now), () -> new TeamMessage.Location(u, -u, u, 0));
                for (ChannelEvent e : out.events()) if (e instanceof ChannelEvent.ActionReceived) received[u]++;
                if (out.say() != null) said.add(new Said(u, out.say()));
            }
            assertTrue(said.size() <= 3, "at most three speakers, so the server delivers every message: " + said.size() + " in " + c);
            air.put(c + 2, said);
            speakers.put(c, said.stream().map(Said::speaker).toList());
        }
        assertTrue(rounds.size() >= 10, rounds.size() + " rounds in 600 cycles");
        for (ChannelEvent.ReportsComplete r : closed) {
            assertEquals(List.of(), r.missing(), "round " + r.round() + " heard every field player (player 2 reports first after \"s\")");
        }
        // the round the kick-off's "s" began: said at the change, player 2 reports 2 cycles later when it has heard it
        assertEquals(List.of(1), speakers.get(KICK_OFF), "\"s\" at the kick-off");
        assertEquals(List.of(2), speakers.get(KICK_OFF + MJ.startToFirstReportCycles()), "player 2 reports once it has heard \"s\"");
        for (int u = 2; u <= 7; u++) assertTrue(received[u] >= rounds.size() - 1, "player " + u + ": " + received[u] + " orders in " + rounds.size() + " rounds");
        // a round: 6 report cycles, latency, 5 frames, the 20-cycle pause
        long first = closed.get(2).cycle(), next = closed.get(3).cycle();
        assertTrue(next - first <= 35, "a round takes " + (next - first) + " cycles");
    }

    @Test
    void theFirstReportSlotAfterStartComesOnceStartCanBeHeard() {
        assertEquals(2, ChannelConfig.DEFAULT.startToFirstReportCycles(), "SimSpark's 2-cycle slots: one slot, as always");
        assertEquals(3, ChannelConfig.thesis().startToFirstReportCycles(), "the thesis's 3-cycle slots: one slot");
        assertEquals(2, MJ.startToFirstReportCycles(), "1-cycle slots: the latency, 2");
    }

    /** What listener u hears of a cycle's messages: the others' (the server never echoes one's own), unlabelled. */
    private static List<Hear> heardBy(int u, List<Said> said) {
        List<Hear> l = new ArrayList<>();
        for (Said s : said) if (s.speaker() != u) l.add(new Hear(null, 0, false, 0, s.text()));
        return l;
    }

    private record Said(int speaker, String text) {}
}

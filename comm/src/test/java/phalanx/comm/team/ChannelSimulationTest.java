package phalanx.comm.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.team.ChannelSimulation.Opponents;
import phalanx.comm.team.ChannelSimulation.Result;
import phalanx.comm.team.ChannelSimulation.Round;

import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Eleven players through the simulated server (not rcssserver3d). The expected figures follow from the
 * protocol by hand: ten report slots of 2 cycles, heard 2 cycles after the last one is said, then five
 * action messages (nine poses at two a message, the on-ball player's bare action riding along) one slot
 * apart, the last heard 2 cycles later: 20 + 8 + 2 = 30 cycles from the first report slot; the first
 * round adds the slot of its "s".
 */
class ChannelSimulationTest {
    static final int CYCLES = 1000;

    static void assertEveryRound(Result r, int reports, long hearAll, long fullRound) {
        assertEveryRound(r, reports, hearAll, fullRound, 2);
    }

    static void assertEveryRound(Result r, int reports, long hearAll, long fullRound, int slot) {
        assertTrue(r.rounds().size() >= 10, "rounds: " + r.rounds().size());
        assertEquals(hearAll + slot, r.first().hearAll(), "first round, counted from its s");
        assertEquals(fullRound + slot, r.first().fullRound());
        for (Round round : r.steady()) {
            assertEquals(reports, round.reportsHeard(), round.toString());
            assertEquals(reports, round.actionsHeard(), round.toString());
            assertEquals(hearAll, round.hearAll(), round.toString());
            assertEquals(fullRound, round.fullRound(), round.toString());
        }
        assertEquals(0, r.wrongReports());
        assertEquals(0, r.wrongActions());
    }

    @Test
    void noOpponents() {
        Result r = new ChannelSimulation().run(CYCLES);
        assertEveryRound(r, 10, 20, 30);
        // 11 players connect 3 cycles apart; player 11's "i" (slot 21, cycle 42) is heard at 44,
        // which is label 1's slot: "s" at once
        assertEquals(44, r.startSaid());
        assertEquals(0, r.rejected());
    }

    @Test
    void opponentsTalkingEveryCycleChangeNothing() {
        ChannelSimulation sim = new ChannelSimulation();
        sim.opponents = Opponents.RANDOM;
        Result r = sim.run(CYCLES);
        assertEveryRound(r, 10, 20, 30);
        assertTrue(r.rejected() > 0);
    }

    @Test
    void opponentsReplayingOurMessagesOnAnUnlabelledServerAreAllRejected() {
        ChannelSimulation sim = new ChannelSimulation();
        sim.opponents = Opponents.REPLAY;
        sim.labelled = false;
        Result r = sim.run(CYCLES);
        assertEveryRound(r, 10, 20, 30);
        assertTrue(r.rejected() > 1000, "rejected " + r.rejected());
    }

    @Test
    void oneCycleSlotsLoseReportsSoTwoIsTheShortest() {
        ChannelSimulation sim = new ChannelSimulation();
        sim.config = ChannelConfig.DEFAULT.withSlotCycles(1);
        Result r = sim.run(CYCLES);
        assertFalse(r.rounds().isEmpty());
        for (Round round : r.rounds()) assertTrue(round.reportsHeard() <= 5, round.toString());
    }

    @Test
    void thesisThreeCycleSlots() {
        ChannelSimulation sim = new ChannelSimulation();
        sim.config = ChannelConfig.DEFAULT.withSlotCycles(3);
        // last report said 27 cycles after the first slot, heard at 29; five messages 3 apart: 29 + 12 + 2
        assertEveryRound(sim.run(CYCLES), 10, 29, 43, 3);
    }

    @Test
    void aPlayerThatNeverConnectsIsLeftOutAfterTheTimeout() {
        ChannelSimulation sim = new ChannelSimulation();
        sim.absent = Set.of(7);
        Result r = sim.run(CYCLES);
        assertEquals(110, r.startSaid()); // init timeout 100, then the coordinator's next slot
        // its slot stays empty; nine actions fit in four messages
        assertEveryRound(r, 9, 20, 28);
    }
}

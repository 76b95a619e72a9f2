package phalanx.comm.team;

/**
 * Every constant of the team channel in one place. {@link #DEFAULT} is what the team plays with;
 * {@link #thesis()} is the thesis's setting, for comparison runs. Where the default departs from
 * the thesis, the comment says why.
 *
 * @param players                 team size: 11 (server 0.6.6+) or 9 (0.6.5)
 * @param coordinator             uniform number of the coordinator, the goalkeeper (5.1)
 * @param slotCycles              cycles per time slot; thesis 3 (4.7). The server lets a listener hear
 *                                one team-mate message every 2 cycles (AgentState: hear capacity 2,
 *                                cost 2, refill 1 a cycle; S4: m351 lost one cycle after m350), so 2 is
 *                                the shortest slot that loses nothing; 1 loses every other message.
 * @param minLatencyCycles        a say sent in reply to perception c is heard in perception c + 2
 *                                (S4: said after now 2.48, heard at 2.52; DESIGN: reply shows in i+2)
 * @param maxLatencyCycles        one cycle of slack for a reply that reaches a real-time server late.
 *                                Must stay below 2 x min so a replay can never arrive in time.
 * @param computeCycles           cycles between the last report and the first action message;
 *                                thesis 6 (Algorithm 3 spreads the phases); our coordination is meant to
 *                                run in one cycle (DESIGN target < 1 ms), so 0
 * @param roundPauseCycles        pause after a dispatch before the next round's reports; thesis 20 (5.3)
 * @param initTimeoutCycles       the coordinator starts the first round without the missing init
 *                                messages after this long (thesis: no timeout; players connect a few
 *                                cycles apart, 11 players take about 40 cycles to connect)
 * @param inactiveAfterMissedRounds a player whose reports were missing this many rounds in a row is
 *                                inactive: not waited for, reported to the coordination as inactive
 * @param coordinatorSilenceCycles a field player that hears nothing from the coordinator for this long
 *                                acts on its own beliefs; a normal round plus pause keeps the coordinator
 *                                quiet for about 40 cycles, so 100 (2 s) means it is gone
 */
public record ChannelConfig(int players, int coordinator, int slotCycles,
                            int minLatencyCycles, int maxLatencyCycles, int computeCycles,
                            int roundPauseCycles, int initTimeoutCycles, int inactiveAfterMissedRounds,
                            int coordinatorSilenceCycles) {

    public static final ChannelConfig DEFAULT = new ChannelConfig(11, 1, 2, 2, 3, 0, 20, 100, 2, 100);

    /**
     * rcssservermj's ssim rule book (docs/rcssservermj.md, "Say and hear"): 7 players, and slots of 1 cycle. Its
     * hearing has no per-listener capacity (rcsssmj 0.2.1 sim/simulation.py: in each cycle a listener hears the three
     * loudest messages of that cycle always, quieter ones at random), so one speaker a cycle loses nothing where
     * SimSpark needs 2. The latency is SimSpark's (said after perception c, heard in c + 2, measured).
     */
    public static final ChannelConfig MJ = DEFAULT.withPlayers(7).withSlotCycles(1);

    public ChannelConfig {
        if (players < 2 || players > 15) {
            throw new IllegalArgumentException("players must be 2-15 (uniform numbers are 4 bits on the wire), got " + players);
        }
        if (coordinator < 1 || coordinator > players) {
            throw new IllegalArgumentException("coordinator must be a uniform number 1-" + players + ", got " + coordinator);
        }
        if (slotCycles < 1) throw new IllegalArgumentException("slotCycles must be at least 1, got " + slotCycles);
        if (minLatencyCycles < 1) throw new IllegalArgumentException("minLatencyCycles must be at least 1, got " + minLatencyCycles);
        if (maxLatencyCycles < minLatencyCycles || maxLatencyCycles - minLatencyCycles > 3) {
            throw new IllegalArgumentException("maxLatencyCycles must be minLatencyCycles to minLatencyCycles + 3 "
                    + "(the wire carries the said cycle mod 4), got " + minLatencyCycles + ".." + maxLatencyCycles);
        }
        if (maxLatencyCycles >= 2 * minLatencyCycles) {
            throw new IllegalArgumentException("maxLatencyCycles " + maxLatencyCycles + " must be below 2 x minLatencyCycles "
                    + "= " + 2 * minLatencyCycles + ", or an opponent could replay a message it just heard in time");
        }
        if (computeCycles < 0 || roundPauseCycles < 0 || initTimeoutCycles < 0) {
            throw new IllegalArgumentException("computeCycles, roundPauseCycles and initTimeoutCycles must not be negative");
        }
        if (inactiveAfterMissedRounds < 1) {
            throw new IllegalArgumentException("inactiveAfterMissedRounds must be at least 1, got " + inactiveAfterMissedRounds);
        }
        if (coordinatorSilenceCycles < 1) {
            throw new IllegalArgumentException("coordinatorSilenceCycles must be at least 1, got " + coordinatorSilenceCycles);
        }
    }

    /** The thesis's setting: 3-cycle slots (4.7), coordination over 6 cycles (Algorithm 3), 20-cycle pause (5.3). */
    public static ChannelConfig thesis() {
        return new ChannelConfig(11, 1, 3, 2, 3, 6, 20, 100, 2, 100);
    }

    public ChannelConfig withPlayers(int n) {
        return new ChannelConfig(n, coordinator, slotCycles, minLatencyCycles, maxLatencyCycles, computeCycles,
                roundPauseCycles, initTimeoutCycles, inactiveAfterMissedRounds, coordinatorSilenceCycles);
    }

    public ChannelConfig withSlotCycles(int n) {
        return new ChannelConfig(players, coordinator, n, minLatencyCycles, maxLatencyCycles, computeCycles,
                roundPauseCycles, initTimeoutCycles, inactiveAfterMissedRounds, coordinatorSilenceCycles);
    }

    public ChannelConfig withRoundPauseCycles(int n) {
        return new ChannelConfig(players, coordinator, slotCycles, minLatencyCycles, maxLatencyCycles, computeCycles,
                n, initTimeoutCycles, inactiveAfterMissedRounds, coordinatorSilenceCycles);
    }

    /** Report slot of a field player, 0-based, counted from the round's first report slot. */
    public int reportSlot(int unum) {
        return unum < coordinator ? unum - 1 : unum - 2;
    }

    /**
     * Cycles from a start message ("s") to its round's first report slot: one slot, or when slots are shorter than
     * the latency as many whole slots as it takes for the start to be heard. With rcssservermj's 1-cycle slots a first
     * slot one cycle after "s" came before anyone could have heard it, and player 2's report was lost in every round
     * a start began (MjTeamTest on the real server). 2 on SimSpark's 2-cycle slots, as before.
     */
    public int startToFirstReportCycles() {
        return slotCycles * Math.max(1, (minLatencyCycles + slotCycles - 1) / slotCycles);
    }

    /** Number of field players, each owning one report slot per round. */
    public int fieldPlayers() {
        return players - 1;
    }

    /** The pause rounded up to whole slots, so every round stays on the slot grid. */
    public int pauseSlots() {
        return (roundPauseCycles + slotCycles - 1) / slotCycles;
    }
}

package phalanx.comm.team;

/**
 * Time cut into slots of {@code slotCycles} cycles, one labelled speaker per slot (thesis 4.7): the
 * label runs 1, 2, ..., players, 1, ... one step per slot, and restarts at 1 when the play mode
 * changes, a moment every player sees in the same cycle. Until the first change the slots count from
 * cycle 0 of the server clock, which every player shares (the {@code now} of each perception), so
 * players that connect at different times agree.
 */
public record TimeSlices(int slotCycles, int players, long epochCycle) {

    public TimeSlices {
        if (slotCycles < 1 || players < 1) throw new IllegalArgumentException("slotCycles and players must be positive");
    }

    public static TimeSlices of(ChannelConfig config) {
        return new TimeSlices(config.slotCycles(), config.players(), 0);
    }

    /** The cycle number of a perception with this {@code (time (now t))}: cycles are 20 ms. */
    public static long cycleOf(double serverTime) {
        return Math.round(serverTime * 50);
    }

    public long slot(long cycle) {
        return Math.floorDiv(cycle - epochCycle, slotCycles);
    }

    public boolean isSlotStart(long cycle) {
        return Math.floorMod(cycle - epochCycle, slotCycles) == 0;
    }

    /** The uniform number allowed to speak in the slot holding this cycle. */
    public int label(long cycle) {
        return (int) Math.floorMod(slot(cycle), (long) players) + 1;
    }

    /** The slices after a play-mode change seen in this cycle: label 1 speaks now. */
    public TimeSlices restartedAt(long cycle) {
        return new TimeSlices(slotCycles, players, cycle);
    }
}

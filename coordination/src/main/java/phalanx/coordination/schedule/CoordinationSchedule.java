package phalanx.coordination.schedule;

import java.util.Optional;
import phalanx.coordination.CoordinationRun;
import phalanx.coordination.Coordinator;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.TeamBeliefs;

/**
 * Algorithm 3 as a scheduler over simulation cycles. The thesis spreads one round over six cycles so that
 * each group of phases fits one think cycle:
 * <ol>
 * <li>update beliefs</li><li>subsets</li><li>active positions</li><li>active mapping</li>
 * <li>formation, roles, support positions</li><li>support mapping, actions</li>
 * </ol>
 * With {@link #singleCycle} all six run in the cycle the round starts, which is what a round measured
 * well under the cycle budget allows ({@link #fitting}).
 */
public final class CoordinationSchedule {
    /** Cycles the thesis's schedule takes. */
    public static final int THESIS_CYCLES = 6;

    private final Coordinator coordinator;
    private final boolean singleCycle;
    private CoordinationRun run;

    public CoordinationSchedule(Coordinator coordinator, boolean singleCycle) {
        this.coordinator = coordinator;
        this.singleCycle = singleCycle;
    }

    /**
     * The setting for a measured round: a single cycle when the round's measured cost (for instance the
     * p99 from {@code scripts/phalanx bench coord}) fits the budget the coordinator may spend per cycle.
     */
    public static CoordinationSchedule fitting(Coordinator coordinator, double budgetMicros, double roundMicros) {
        return new CoordinationSchedule(coordinator, roundMicros <= budgetMicros);
    }

    public boolean singleCycle() { return singleCycle; }

    /** True while a round is under way. */
    public boolean busy() { return run != null; }

    /** Starts a round with the reports gathered so far; refuses while one is under way. */
    public void start(TeamBeliefs beliefs, Mode mode, Memory previous) {
        if (busy()) throw new IllegalStateException("a coordination round is under way (" + run.phasesDone() + " of 6 phases done)");
        run = coordinator.start(beliefs, mode, previous);
    }

    /** Runs this cycle's phases; the plan when the round finished in this cycle. */
    public Optional<TeamPlan> cycle() {
        if (run == null) return Optional.empty();
        do {
            switch (run.phasesDone()) {
                case 0 -> run.updateBeliefs();
                case 1 -> run.determineSubsets();
                case 2 -> run.determineActivePositions();
                case 3 -> run.coordinateActivePlayers();
                case 4 -> run.formationRolesAndSupportPositions();
                default -> {
                    TeamPlan plan = run.coordinateSupportPlayers();
                    run = null;
                    return Optional.of(plan);
                }
            }
        } while (singleCycle);
        return Optional.empty();
    }
}

package phalanx.coordination;

import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.coordination.formation.FormationGenerator;
import phalanx.coordination.formation.FormationSource;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.support.SupportMapper;

/**
 * The goalkeeper's team coordination (thesis chapter 5): the team's reports and the mode in, one
 * assignment per player out. Pure: no clock, no socket, no state of its own; the previous plan is passed
 * in ({@link TeamPlan#memory()}) for the on-ball hysteresis (5.8) and as the ball of last resort.
 */
public final class Coordinator {
    private final CoordinationConfig config;
    private final SupportMapper supportMapper;
    private final FormationSource formations;

    /** With the thesis formation generator (5.9) for the field of the round's beliefs. */
    public Coordinator(CoordinationConfig config, SupportMapper supportMapper) {
        this(config, supportMapper, config == null ? null : (ball, field) -> FormationGenerator.generate(ball, field, config.formation()));
    }

    /** With another formation (rcssservermj: {@link phalanx.coordination.formation.StretchedFormation}). */
    public Coordinator(CoordinationConfig config, SupportMapper supportMapper, FormationSource formations) {
        if (config == null || supportMapper == null || formations == null)
            throw new IllegalArgumentException("config, support mapper and formation source are needed");
        this.config = config;
        this.supportMapper = supportMapper;
        this.formations = formations;
    }

    /** The thesis's constants and its support mapping (Algorithm 5). */
    public Coordinator() { this(CoordinationConfig.THESIS, new DynamicProgrammingSupportMapper()); }

    public CoordinationConfig config() { return config; }

    /**
     * All six phases of Algorithm 3 at once.
     *
     * @param previous what the previous round left ({@link TeamPlan#memory()}), or {@link Memory#NONE}
     */
    public TeamPlan coordinate(TeamBeliefs beliefs, Mode mode, Memory previous) {
        CoordinationRun run = start(beliefs, mode, previous);
        run.updateBeliefs();
        run.determineSubsets();
        run.determineActivePositions();
        run.coordinateActivePlayers();
        run.formationRolesAndSupportPositions();
        return run.coordinateSupportPlayers();
    }

    /** A round whose phases the caller runs one by one (see {@code schedule.CoordinationSchedule}). */
    public CoordinationRun start(TeamBeliefs beliefs, Mode mode, Memory previous) {
        return new CoordinationRun(config, supportMapper, formations, beliefs, mode, previous);
    }
}

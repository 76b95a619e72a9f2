package phalanx.coordination;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import phalanx.coordination.active.ActiveMapper;
import phalanx.coordination.active.ActivePositions;
import phalanx.coordination.active.OnBallChooser;
import phalanx.coordination.beliefs.BeliefsUpdate;
import phalanx.coordination.beliefs.GlobalBeliefs;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.coordination.formation.Formation;
import phalanx.coordination.formation.FormationSource;
import phalanx.coordination.formation.Role;
import phalanx.coordination.formation.RoleAssignment;
import phalanx.coordination.subsets.Subset;
import phalanx.coordination.subsets.Subsets;
import phalanx.coordination.support.SupportCost;
import phalanx.coordination.support.SupportMapper;
import phalanx.coordination.support.SupportMapping;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * One coordination round, phase by phase (Algorithm 3). Each method is one phase and must be called in
 * order; {@link Coordinator} calls them all at once, {@code schedule.CoordinationSchedule} spreads them
 * over cycles. Not thread-safe; one instance per round.
 */
public final class CoordinationRun {
    private final CoordinationConfig config;
    private final SupportMapper supportMapper;
    private final FormationSource formations;
    private final TeamBeliefs input;
    private final Mode mode;
    private final Memory previous;

    private GlobalBeliefs beliefs;
    private Subsets subsets;
    private List<Vector2> candidates = List.of();
    private int onBall;
    private final Map<Integer, Vector2> activeTargets = new java.util.LinkedHashMap<>();
    private Formation formation;
    private RoleAssignment roles;
    private TeamPlan plan;
    private int done;

    CoordinationRun(CoordinationConfig config, SupportMapper supportMapper, FormationSource formations, TeamBeliefs input,
                    Mode mode, Memory previous) {
        if (input == null || mode == null) throw new IllegalArgumentException("beliefs and mode are needed");
        this.config = config;
        this.supportMapper = supportMapper;
        this.formations = formations;
        this.input = input;
        this.mode = mode;
        this.previous = previous == null ? Memory.NONE : previous;
    }

    private void step(int phase) {
        if (done != phase - 1) throw new IllegalStateException("phase " + phase + " called after phase " + done);
        done = phase;
    }

    /** How many phases have run (0..6). */
    public int phasesDone() { return done; }

    /** Phase 1, "Update Coordination Beliefs" (5.4). */
    public void updateBeliefs() {
        step(1);
        beliefs = BeliefsUpdate.update(input, config.ballClusterThreshold(), config.ballClusterExponent(),
                previous.ball());
    }

    /** Phase 2, "Determine Coordination Subsets" (5.5, modes 5.2). */
    public void determineSubsets() {
        step(2);
        subsets = Subsets.split(beliefs, mode, config.goalkeeperId(), config.activeCount());
    }

    /** Phase 3, "Determine Active Positions" (5.7). */
    public void determineActivePositions() {
        step(3);
        if (!subsets.active().isEmpty())
            candidates = ActivePositions.candidates(beliefs.ball(), beliefs.field(), config.activePositions());
    }

    /** Phase 4, "Coordinate Active Players" (5.8, Algorithm 4). */
    public void coordinateActivePlayers() {
        step(4);
        List<Integer> active = subsets.active();
        if (active.isEmpty()) return;
        FieldSpec field = beliefs.field();
        Vector2 ball = beliefs.ball();
        List<PlayerBelief> activeBeliefs = new ArrayList<>(active.size());
        for (int id : active) activeBeliefs.add(beliefs.player(id));
        int previousOnBall = previous.onBall();
        onBall = OnBallChooser.choose(activeBeliefs, ball, field.opponentGoal(), config.onBall(), previousOnBall);

        List<Integer> others = new ArrayList<>(active);
        others.remove(Integer.valueOf(onBall));
        // Active players nearest the ball first; the farthest ones go to support when candidates run out.
        List<Integer> demoted = new ArrayList<>();
        while (others.size() > candidates.size()) demoted.add(others.remove(others.size() - 1));
        if (!demoted.isEmpty()) subsets = subsets.demote(demoted);

        List<Vector2> starts = new ArrayList<>(others.size());
        for (int id : others) starts.add(beliefs.player(id).position());
        ActiveMapper.ActiveMapping m = ActiveMapper.map(beliefs.player(onBall).position(), ball, starts, candidates,
                field, config.activeWeights(), config.collision());
        activeTargets.put(onBall, ball);
        for (int i = 0; i < others.size(); i++) activeTargets.put(others.get(i), candidates.get(m.assignment()[i]));
    }

    /** Phase 5, "Generate Team Formation", "Assign Team Roles", "Determine Support Positions" (5.9-5.11). */
    public void formationRolesAndSupportPositions() {
        step(5);
        formation = formations.generate(beliefs.ball(), beliefs.field());
        roles = RoleAssignment.assign(formation, beliefs.ball(), new ArrayList<>(activeTargets.values()),
                subsets.support().size());
    }

    /** Phase 6, "Coordinate Support Players" (5.12, Algorithm 5); returns the plan. */
    public TeamPlan coordinateSupportPlayers() {
        step(6);
        Vector2 ball = beliefs.ball();
        Vector2 goal = beliefs.field().opponentGoal();
        List<Integer> support = subsets.support();
        List<Vector2> agents = new ArrayList<>(support.size()), positions = new ArrayList<>(support.size());
        for (int id : support) agents.add(beliefs.player(id).position());
        for (Role r : roles.supportRoles()) positions.add(formation.position(r));
        List<Vector2> fixedStarts = new ArrayList<>(), fixedTargets = new ArrayList<>();
        for (Map.Entry<Integer, Vector2> e : activeTargets.entrySet()) {
            fixedStarts.add(beliefs.player(e.getKey()).position());
            fixedTargets.add(e.getValue());
        }
        SupportMapping mapping = supportMapper.map(new SupportCost(agents, positions, fixedStarts, fixedTargets,
                config.supportWeights(), config.collision()));

        Map<Integer, Assignment> out = new java.util.TreeMap<>();
        List<Role> activeRoles = roles.activeRoles();
        int i = 0;
        for (Map.Entry<Integer, Vector2> e : activeTargets.entrySet()) {
            int id = e.getKey();
            boolean isOnBall = id == onBall;
            Vector2 t = e.getValue();
            double heading = isOnBall ? goal.minus(ball).angleDeg() : facing(t, ball);
            out.put(id, new Assignment(id, Subset.ACTIVE, isOnBall ? Action.ON_BALL : Action.ACTIVE_POSITION,
                    activeRoles.get(i++), t, heading));
        }
        for (int s = 0; s < support.size(); s++) {
            int p = mapping.positionOf()[s];
            Vector2 t = positions.get(p);
            out.put(support.get(s), new Assignment(support.get(s), Subset.SUPPORT, Action.SUPPORT_POSITION,
                    roles.supportRoles().get(p), t, facing(t, ball)));
        }
        Action idle = mode == Mode.WAIT ? Action.WAIT : Action.LOCALIZE;
        for (int id : subsets.inactive())
            out.put(id, new Assignment(id, Subset.INACTIVE, idle, null, null, Double.NaN));
        if (subsets.goalkeeper() != 0) {
            Vector2 t = formation.position(Role.GK);
            out.put(subsets.goalkeeper(), new Assignment(subsets.goalkeeper(), Subset.GOALKEEPER, Action.GOALKEEPER,
                    Role.GK, t, facing(t, ball)));
        }
        plan = new TeamPlan(mode, beliefs, subsets, ActivePositions.defensive(ball), candidates, formation,
                roles.dropped(), new ArrayList<>(out.values()), mapping.evaluated());
        return plan;
    }

    /** The finished plan, or null before phase 6. */
    public TeamPlan plan() { return plan; }

    private static double facing(Vector2 from, Vector2 ball) {
        Vector2 d = ball.minus(from);
        return d.norm() < 1e-9 ? 0 : d.angleDeg();
    }
}

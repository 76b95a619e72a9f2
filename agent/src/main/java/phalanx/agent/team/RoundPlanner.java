package phalanx.agent.team;

import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.comm.team.round.CoordinationProcedure;
import phalanx.comm.team.round.RoundReports;
import phalanx.comm.team.TeamMessage;
import phalanx.coordination.Assignment;
import phalanx.coordination.Coordinator;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import java.util.logging.Logger;

/**
 * The goalkeeper's side of chapter 5: when the team channel has a round's reports, add the
 * goalkeeper's own, run the coordination (phalanx.coordination) and turn its assignments into the
 * action messages field players carry out.
 */
public final class RoundPlanner implements CoordinationProcedure {
    private static final Logger LOG = Logger.getLogger(RoundPlanner.class.getName());

    private final Coordinator coordinator;
    private final FieldSpec field;
    private final int selfUnum;
    private final Supplier<Own> own;
    private final Supplier<PlayMode> playMode;
    private final BooleanSupplier goalkeeperHasBall;
    private Memory memory = Memory.NONE;
    private TeamPlan lastPlan;
    /** Each field player's last report heard, with the round it was heard in. */
    private final java.util.Map<Integer, Heard> lastHeard = new java.util.TreeMap<>();

    private record Heard(int round, TeamMessage.Report report) {}

    /**
     * What the coordinator adds of its own to a round: its report, the side we play on (null: unknown, taken as
     * left) and its own ball, the ball of last resort when no report has one (null: none).
     */
    public record Own(TeamMessage.Report report, Side side, Vector2 ball) {
        /** The goalkeeper's beliefs on SimSpark. */
        public static Own of(int unum, WorldBelief b) {
            return new Own(Reports.of(unum, b), b == null ? null : b.side(), b == null ? null : b.ballGlobal());
        }
    }

    /** On SimSpark: the coordinator's own beliefs are its belief store's. */
    public RoundPlanner(Coordinator coordinator, FieldSpec field, int selfUnum, Supplier<WorldBelief> ownBelief,
                            Supplier<PlayMode> playMode, BooleanSupplier goalkeeperHasBall) {
        this(coordinator, field, selfUnum, playMode, goalkeeperHasBall, () -> Own.of(selfUnum, ownBelief.get()));
    }

    /** With the coordinator's own report, side and ball from elsewhere (rcssservermj: {@code MjTeamTalk}). */
    public RoundPlanner(Coordinator coordinator, FieldSpec field, int selfUnum, Supplier<PlayMode> playMode,
                        BooleanSupplier goalkeeperHasBall, Supplier<Own> own) {
        this.coordinator = coordinator;
        this.field = field;
        this.selfUnum = selfUnum;
        this.own = own;
        this.playMode = playMode;
        this.goalkeeperHasBall = goalkeeperHasBall;
    }

    @Override public List<Action> actions(RoundReports round) {
        Own me = own.get();
        Side side = me.side() == null ? Side.LEFT : me.side();
        List<PlayerReport> reports = new ArrayList<>();
        reports.add(Reports.toCoordination(me.report()));
        for (TeamMessage.Report r : round.reports().values()) {
            if (r.sender() == selfUnum) continue;
            reports.add(Reports.toCoordination(r));
            lastHeard.put(r.sender(), new Heard(round.round(), r));
        }
        // A report lost on the channel drops its player from the round's plan, and On Ball went to a player 12 m
        // from the ball (docs/matches.md, session 15). The channel counts a player inactive after
        // inactiveAfterMissedRounds (2) rounds; until then, one round missing, its previous round's report stands in.
        for (Heard h : lastHeard.values()) {
            int u = h.report().sender();
            if (h.round() == round.round() - 1 && !round.reports().containsKey(u) && !round.inactive().contains(u)) {
                reports.add(Reports.toCoordination(h.report()));
            }
        }
        Mode mode = Mode.of(playMode.get(), side, goalkeeperHasBall.getAsBoolean());
        TeamPlan plan;
        try {
            plan = coordinator.coordinate(new TeamBeliefs(field, reports, me.ball()), mode, memory);
        } catch (RuntimeException e) {
            // A bad round (a report the coordination refuses) must not stop the team: skip it.
            LOG.warning("coordination round " + round.round() + " skipped: " + e.getMessage());
            return List.of();
        }
        if (plan.onBall() != memory.onBall()) logOnBallChange(round.round(), memory.onBall(), plan);
        memory = plan.memory();
        lastPlan = plan;
        List<Action> out = new ArrayList<>();
        for (PlayerReport r : reports) {
            if (r.id() == selfUnum) continue;
            Assignment a = plan.assignment(r.id());
            if (a != null) out.add(order(a));
        }
        return out;
    }

    /**
     * One line when On Ball moves to another player: the ball and each active player's report type, position and
     * ball distance as the coordinator had them, so a match review can tell why a player at the ball lost it.
     */
    private static void logOnBallChange(int round, int from, TeamPlan plan) {
        StringBuilder sb = new StringBuilder(160);
        sb.append(String.format(Locale.ROOT, "round %d: On Ball %d -> %d, ball (%.2f,%.2f);", round, from, plan.onBall(),
                plan.ball().x(), plan.ball().y()));
        List<Integer> shown = new ArrayList<>(plan.subsets().active());
        if (from > 0 && !shown.contains(from)) shown.add(from);
        for (int id : shown) {
            PlayerBelief p = plan.beliefs().player(id);
            if (p == null) { sb.append(' ').append(id).append(":none"); continue; }
            sb.append(String.format(Locale.ROOT, " %d:%s%s", id, p.type(), p.fallen() ? "/fallen" : ""));
            if (p.position() != null) sb.append(String.format(Locale.ROOT, " (%.2f,%.2f) d=%.2f", p.position().x(), p.position().y(), p.ballDistance()));
            if (!plan.subsets().active().contains(id)) sb.append(" (not active)");
        }
        LOG.info(sb.toString());
    }

    /** The last plan computed, for debug drawing; null before the first round. */
    public TeamPlan lastPlan() { return lastPlan; }

    static Action order(Assignment a) {
        return switch (a.action()) {
            case ON_BALL -> Action.of(a.id(), ActionId.ON_BALL);
            case ACTIVE_POSITION, SUPPORT_POSITION -> Action.walkTo(a.id(), a.target().x(), a.target().y(), a.orientationDeg());
            case LOCALIZE -> Action.of(a.id(), ActionId.TURN_TO_LOCALIZE);
            case WAIT, GOALKEEPER -> Action.of(a.id(), ActionId.LOOK_STRAIGHT);
        };
    }
}

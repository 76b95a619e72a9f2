package phalanx.agent.team;

import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.round.ChannelEvent;
import phalanx.comm.team.round.ChannelOutput;
import phalanx.comm.team.round.CoordinatorRounds;
import phalanx.comm.team.round.FieldPlayerRounds;
import phalanx.comm.team.SayCodec;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessageCodec;
import phalanx.comm.team.TimeSlices;
import phalanx.comm.team.TeamMessage;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.logging.Logger;

/**
 * The player's end of the say/hear channel (thesis 4.7, 5.3): the coordinator's state machine on
 * the goalkeeper, the field player's on the others. Stepped once a cycle; gives what to say, and
 * on a field player the coordinator's last order and whether the coordinator has gone quiet.
 */
public final class TeamChannel {
    private static final Logger LOG = Logger.getLogger(TeamChannel.class.getName());

    private final CoordinatorRounds coordinator;   // player 1
    private final FieldPlayerRounds fieldPlayer;   // players 2..n
    private final int unum;
    private final RoundPlanner procedure;   // player 1
    /** The teammates' ball reports heard in the last step (issue 19). */
    private final List<HeardBall> heardBalls = new ArrayList<>();
    private final List<TeamMessage.Report> heardReports = new ArrayList<>();
    /** Rounds and the reports they heard as one value: another thread (a test, a status line) reads both at once. */
    public record RoundCount(long rounds, long reports) {}

    private volatile RoundCount roundCount = new RoundCount(0, 0);
    private long actionsDispatched, actionsReceived;
    private int lastRoundHeard;

    /** A teammate's ball, in the own frame, said at server time {@code time}. */
    public record HeardBall(int sender, Vector2 ball, double time) {}

    private TeamChannel(CoordinatorRounds coordinator, FieldPlayerRounds fieldPlayer, int unum, RoundPlanner procedure) {
        this.coordinator = coordinator;
        this.fieldPlayer = fieldPlayer;
        this.unum = unum;
        this.procedure = procedure;
    }

    public static TeamChannel coordinator(ChannelConfig config, TeamKey key, String team, RoundPlanner procedure) {
        return coordinator(config, new TeamMessageCodec(key, config), team, procedure);
    }

    public static TeamChannel fieldPlayer(ChannelConfig config, TeamKey key, String team, int unum) {
        return fieldPlayer(config, new TeamMessageCodec(key, config), team, unum);
    }

    /** With the codec of the server played on (rcssservermj: {@code MjTeamMessageCodec.text()}). */
    public static TeamChannel coordinator(ChannelConfig config, SayCodec codec, String team, RoundPlanner procedure) {
        return new TeamChannel(new CoordinatorRounds(config, codec, team, procedure), null, config.coordinator(), procedure);
    }

    /** With the codec of the server played on (rcssservermj: {@code MjTeamMessageCodec.text()}). */
    public static TeamChannel fieldPlayer(ChannelConfig config, SayCodec codec, String team, int unum) {
        return new TeamChannel(null, new FieldPlayerRounds(config, unum, codec, team), unum, null);
    }

    /** On the goalkeeper, the last coordination round's plan (for debug drawing); else null. */
    public phalanx.coordination.TeamPlan lastPlan() { return procedure == null ? null : procedure.lastPlan(); }

    /** One cycle: returns the text to say, or null. */
    public String step(double serverTime, PlayMode mode, List<Hear> heard, WorldBelief belief) {
        return step(TimeSlices.cycleOf(serverTime), mode, heard, () -> Reports.of(unum, belief));
    }

    /**
     * One cycle numbered by the caller (rcssservermj: {@code MjTeamMessageCodec.cycleOf}); {@code report} is this
     * field player's report, asked for only in its report slot. Returns the text to say, or null.
     */
    public String step(long cycle, PlayMode mode, List<Hear> heard, Supplier<TeamMessage.Report> report) {
        ChannelOutput out = coordinator != null ? coordinator.step(cycle, mode, heard) : fieldPlayer.step(cycle, mode, heard, report);
        heardBalls.clear();
        heardReports.clear();
        for (ChannelEvent e : out.events()) {
            if (e instanceof ChannelEvent.ReportHeard h) heardReports.add(h.report());
            if (e instanceof ChannelEvent.ReportHeard h && h.report() instanceof TeamMessage.Complete c) {
                heardBalls.add(new HeardBall(c.sender(), new Vector2(c.ballX(), c.ballY()), h.saidCycle() / 50.0));
            }
            if (e instanceof ChannelEvent.ReportsComplete r) {
                lastRoundHeard = r.heard();   // counted once its actions are out: a play-mode change may drop the round
            } else if (e instanceof ChannelEvent.ActionsDispatched d) {
                roundCount = new RoundCount(roundCount.rounds() + 1, roundCount.reports() + lastRoundHeard);
                actionsDispatched += d.actions();
            } else if (e instanceof ChannelEvent.ActionReceived) {
                actionsReceived++;
            }
            // Round boundaries at INFO (a few lines a second on the goalkeeper: the data for the
            // channel's real-server figures); the rest at FINE.
            if (e instanceof ChannelEvent.ReportsComplete || e instanceof ChannelEvent.ActionsDispatched
                    || e instanceof ChannelEvent.RoundStarted || e instanceof ChannelEvent.PlayerInactive) {
                LOG.info("team channel: " + e);
            } else {
                LOG.fine(() -> "team channel: " + e);
            }
        }
        return out.say();
    }

    /** The teammates' ball reports ("C") heard in the last step, for the ball belief (BeliefStore.teamBall). */
    public List<HeardBall> heardBalls() { return heardBalls; }

    /** Every teammate report (C, L, B, X) heard in the last step. */
    public List<TeamMessage.Report> heardReports() { return heardReports; }

    /** On the coordinator: rounds whose actions were all said, the reports those rounds heard, the actions sent. */
    public long rounds() { return roundCount.rounds(); }
    public long reportsInRounds() { return roundCount.reports(); }
    public RoundCount roundCount() { return roundCount; }
    public long actionsDispatched() { return actionsDispatched; }

    /** On a field player: the orders addressed to it that it heard. */
    public long actionsReceived() { return actionsReceived; }

    /** Heard texts dropped for this reason so far (foreign, broken, replayed). */
    public long rejected(TeamMessageCodec.Rejection reason) {
        return coordinator != null ? coordinator.rejected(reason) : fieldPlayer.rejected(reason);
    }

    /** The coordinator's last order to this field player, or null (none yet, or on the goalkeeper). */
    public Action order() { return fieldPlayer == null ? null : fieldPlayer.currentAction(); }

    /** True on a field player whose coordinator has gone quiet: act on own beliefs. */
    public boolean coordinatorQuiet() {
        return fieldPlayer != null && fieldPlayer.mode() == FieldPlayerRounds.Mode.AUTONOMOUS;
    }
}

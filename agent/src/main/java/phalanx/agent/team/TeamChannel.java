package phalanx.agent.team;

import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.round.ChannelEvent;
import phalanx.comm.team.round.ChannelOutput;
import phalanx.comm.team.round.CoordinatorRounds;
import phalanx.comm.team.round.FieldPlayerRounds;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TimeSlices;
import phalanx.comm.team.TeamMessage;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;
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

    /** A teammate's ball, in the own frame, said at server time {@code time}. */
    public record HeardBall(int sender, Vector2 ball, double time) {}

    private TeamChannel(CoordinatorRounds coordinator, FieldPlayerRounds fieldPlayer, int unum, RoundPlanner procedure) {
        this.coordinator = coordinator;
        this.fieldPlayer = fieldPlayer;
        this.unum = unum;
        this.procedure = procedure;
    }

    public static TeamChannel coordinator(ChannelConfig config, TeamKey key, String team, RoundPlanner procedure) {
        return new TeamChannel(new CoordinatorRounds(config, key, team, procedure), null, config.coordinator(), procedure);
    }

    public static TeamChannel fieldPlayer(ChannelConfig config, TeamKey key, String team, int unum) {
        return new TeamChannel(null, new FieldPlayerRounds(config, unum, key, team), unum, null);
    }

    /** On the goalkeeper, the last coordination round's plan (for debug drawing); else null. */
    public phalanx.coordination.TeamPlan lastPlan() { return procedure == null ? null : procedure.lastPlan(); }

    /** One cycle: returns the text to say, or null. */
    public String step(double serverTime, PlayMode mode, List<Hear> heard, WorldBelief belief) {
        long cycle = TimeSlices.cycleOf(serverTime);
        ChannelOutput out = coordinator != null ? coordinator.step(cycle, mode, heard)
                : fieldPlayer.step(cycle, mode, heard, () -> Reports.of(unum, belief));
        heardBalls.clear();
        for (ChannelEvent e : out.events()) {
            if (e instanceof ChannelEvent.ReportHeard h && h.report() instanceof TeamMessage.Complete c) {
                heardBalls.add(new HeardBall(c.sender(), new Vector2(c.ballX(), c.ballY()), h.saidCycle() / 50.0));
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

    /** The coordinator's last order to this field player, or null (none yet, or on the goalkeeper). */
    public Action order() { return fieldPlayer == null ? null : fieldPlayer.currentAction(); }

    /** True on a field player whose coordinator has gone quiet: act on own beliefs. */
    public boolean coordinatorQuiet() {
        return fieldPlayer != null && fieldPlayer.mode() == FieldPlayerRounds.Mode.AUTONOMOUS;
    }
}

package phalanx.comm.team.round;

import phalanx.comm.team.Action;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.Listener;
import phalanx.comm.team.SayCodec;
import phalanx.comm.team.TimeSlices;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessageCodec;
import phalanx.comm.team.TeamMessage;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * A field player's side of thesis 5.3, as a state machine stepped once a cycle.
 *
 * <pre>
 * AUTONOMOUS   no word from the coordinator yet (or for coordinatorSilenceCycles): say "i" in its own
 *              labelled slot (4.7) while no round is heard going on, and act on its own beliefs.
 * COORDINATED  every "s", "a" or "e" from the coordinator gives the cycle of its next report slot:
 *              slot (u - 2) after "s" (counted from the first slot "s" can have been heard in,
 *              {@link ChannelConfig#startToFirstReportCycles}), or, after an "a" with r more to come, (r + 1)
 *              slots plus the pause later, then (u - 2) slots more. It says its report exactly then, and keeps the
 *              last action addressed to it until the next one.
 * </pre>
 * A play-mode change voids the schedule: the coordinator starts a new round at once.
 *
 * <p>Fallback when the coordinator goes quiet ({@link ChannelEvent.CoordinatorSilent}): the last
 * action is dropped ({@link #currentAction()} is null) and the agent acts on its own beliefs, as
 * before the first round: if it sees the ball and is the closest player it sees to it, On Ball;
 * otherwise Walk to Coordinate to its formation position for its uniform number, facing the ball.
 * Meanwhile it announces itself again so a restarted coordinator finds it.
 */
public final class FieldPlayerRounds {
    private static final Logger LOG = Logger.getLogger(FieldPlayerRounds.class.getName());
    private static final long NONE = Long.MIN_VALUE;

    public enum Mode { AUTONOMOUS, COORDINATED }

    private final ChannelConfig config;
    private final int self;
    private final SayCodec codec;
    private final Listener listener;

    private TimeSlices slices;
    private PlayMode playMode;
    private Mode mode = Mode.AUTONOMOUS;
    private long reportAt = NONE;
    private long lastCoordinator = NONE;
    private long lastRoundTraffic = NONE;
    private Action current;

    /** On SimSpark: the 20-character codec ({@link TeamMessageCodec}). */
    public FieldPlayerRounds(ChannelConfig config, int unum, TeamKey key, String teamName) {
        this(config, unum, new TeamMessageCodec(key, config), teamName);
    }

    /** With the codec of the server played on (rcssservermj: {@code MjTeamMessageCodec.text()}). */
    public FieldPlayerRounds(ChannelConfig config, int unum, SayCodec codec, String teamName) {
        if (unum < 1 || unum > config.players() || unum == config.coordinator()) {
            throw new IllegalArgumentException("a field player's uniform number must be 1-" + config.players()
                    + " and not the coordinator's (" + config.coordinator() + "), got " + unum);
        }
        this.config = config;
        this.self = unum;
        this.codec = codec;
        this.listener = new Listener(codec, teamName);
        this.slices = TimeSlices.of(config);
    }

    /**
     * One cycle. {@code report} is asked only in this player's report cycle; it returns this player's
     * coordination message (null: nothing known, sent as "X").
     */
    public ChannelOutput step(long cycle, PlayMode mode, List<Hear> heard, Supplier<TeamMessage.Report> report) {
        List<ChannelEvent> events = null;
        if (mode != null && playMode != null && mode != playMode) {
            slices = slices.restartedAt(cycle);
            reportAt = NONE;
        }
        if (mode != null) playMode = mode;

        if (heard != null) {
            for (Hear h : heard) {
                Decoded d = listener.accept(h, cycle);
                if (d != null) events = heardMessage(d, cycle, events);
            }
        }

        if (this.mode == Mode.COORDINATED && cycle - lastCoordinator > config.coordinatorSilenceCycles()) {
            this.mode = Mode.AUTONOMOUS;
            current = null;
            reportAt = NONE;
            events = add(events, new ChannelEvent.CoordinatorSilent(cycle));
        }

        String say = null;
        if (reportAt != NONE && cycle >= reportAt) {
            // a missed report cycle is skipped: said late it would land in the next player's slot
            if (cycle == reportAt) say = report(report, cycle);
            reportAt = NONE;
        } else if (this.mode == Mode.AUTONOMOUS && reportAt == NONE && slices.isSlotStart(cycle) && slices.label(cycle) == self
                && (lastRoundTraffic == NONE || cycle - lastRoundTraffic > (long) config.players() * config.slotCycles())) {
            say = codec.encode(new TeamMessage.Init(self), cycle);
        }
        if (say == null && events == null) return ChannelOutput.NOTHING;
        return new ChannelOutput(say, events);
    }

    private String report(Supplier<TeamMessage.Report> source, long cycle) {
        TeamMessage.Report r = source == null ? null : source.get();
        if (r == null) r = new TeamMessage.Unaware(self, false);
        if (r.sender() != self) {
            throw new IllegalArgumentException("player " + self + " was given a report of player " + r.sender());
        }
        try {
            return codec.encode(r, cycle);
        } catch (IllegalArgumentException e) {
            LOG.log(Level.WARNING, "player " + self + " cannot send its report " + r + " (" + e.getMessage() + "), sends X");
            return codec.encode(new TeamMessage.Unaware(self, false), cycle);
        }
    }

    private List<ChannelEvent> heardMessage(Decoded d, long cycle, List<ChannelEvent> events) {
        TeamMessage m = d.message();
        long slot = config.slotCycles();
        if (m instanceof TeamMessage.Report || m instanceof TeamMessage.Actions) lastRoundTraffic = cycle;
        if (m instanceof TeamMessage.Report r && r.sender() != self) events = add(events, new ChannelEvent.ReportHeard(r, d.saidCycle(), cycle));
        long firstReport;
        if (m instanceof TeamMessage.Start s && s.sender() == config.coordinator()) {
            firstReport = d.saidCycle() + config.startToFirstReportCycles();
        } else if (m instanceof TeamMessage.End e && e.sender() == config.coordinator()) {
            firstReport = d.saidCycle() + slot * (1 + config.pauseSlots());
        } else if (m instanceof TeamMessage.Actions a) {
            firstReport = d.saidCycle() + slot * (a.remaining() + 1 + config.pauseSlots());
            for (Action action : a.actions()) {
                if (action.recipient() == self) {
                    current = action;
                    events = add(events, new ChannelEvent.ActionReceived(action, cycle));
                }
            }
        } else {
            return events;
        }
        reportAt = firstReport + slot * config.reportSlot(self);
        lastCoordinator = cycle;
        if (mode == Mode.AUTONOMOUS) {
            mode = Mode.COORDINATED;
            events = add(events, new ChannelEvent.Coordinated(cycle));
        }
        return events;
    }

    private static List<ChannelEvent> add(List<ChannelEvent> events, ChannelEvent e) {
        if (events == null) events = new ArrayList<>(2);
        events.add(e);
        return events;
    }

    public Mode mode() { return mode; }

    /** The last action the coordinator gave this player, or null (none yet, or the coordinator went quiet). */
    public Action currentAction() { return current; }

    public int unum() { return self; }

    /** How many heard texts were dropped for this reason so far. */
    public long rejected(Rejection reason) { return listener.rejected(reason); }
}

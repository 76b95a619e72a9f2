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
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * The coordinator's side of thesis 5.3 (player 1, the goalkeeper), as a state machine stepped once a
 * cycle with what was heard; it returns what to say and what happened. No clock, no socket.
 *
 * <pre>
 * INIT      gather "i" messages, speaking only in its own labelled slot (4.7); once every field
 *           player has announced itself, or initTimeoutCycles have passed, say "s" in its next slot.
 * REPORTS   field player u reports in slot (u - 2) after the round starts (after "s", from the first slot it
 *           can have been heard in; or when the schedule the last dispatch announced comes). The phase closes once every active player's
 *           report is in, or maxLatency after the last report slot, and never before that slot is over.
 * DISPATCH  call the {@link CoordinationProcedure}, wait computeCycles, then say the action messages one
 *           slot apart ("a", the first one closing the reports; "e" when there is nothing to send).
 * PAUSE     roundPauseCycles of silence, then the next round's reports, with no "s": every "a" and "e"
 *           tells the field players when that is.
 * </pre>
 * A play-mode change drops the round and says "s" at once: the slot labels restart at 1 then.
 * A field player with no report for inactiveAfterMissedRounds rounds is inactive: not waited for, and
 * passed to the procedure as inactive, until it is heard again.
 */
public final class CoordinatorRounds {
    private static final Logger LOG = Logger.getLogger(CoordinatorRounds.class.getName());
    private static final long NONE = Long.MIN_VALUE;

    public enum Phase { INIT, STARTING, REPORTS, DISPATCH, PAUSE }

    private final ChannelConfig config;
    private final SayCodec codec;
    private final Listener listener;
    private final CoordinationProcedure procedure;
    private final int self;

    private TimeSlices slices;
    private PlayMode mode;
    private Phase phase = Phase.INIT;
    private long initDeadline = NONE;
    private final boolean[] known;
    private final boolean[] inactive;
    private final int[] missed;
    private final TeamMessage.Report[] reports;
    private int round;
    private long firstReport = NONE;
    private List<TeamMessage> pending = List.of();
    private int pendingIndex;
    private int pendingActions;
    private long nextSay = NONE;
    private long nextRoundFirstReport = NONE;

    /** On SimSpark: the 20-character codec ({@link TeamMessageCodec}). */
    public CoordinatorRounds(ChannelConfig config, TeamKey key, String teamName, CoordinationProcedure procedure) {
        this(config, new TeamMessageCodec(key, config), teamName, procedure);
    }

    /** With the codec of the server played on (rcssservermj: {@code MjTeamMessageCodec.text()}). */
    public CoordinatorRounds(ChannelConfig config, SayCodec codec, String teamName, CoordinationProcedure procedure) {
        if (procedure == null) throw new IllegalArgumentException("coordination procedure is null");
        this.config = config;
        this.codec = codec;
        this.listener = new Listener(codec, teamName);
        this.procedure = procedure;
        this.self = config.coordinator();
        this.slices = TimeSlices.of(config);
        int n = config.players() + 1;
        known = new boolean[n];
        inactive = new boolean[n];
        missed = new int[n];
        reports = new TeamMessage.Report[n];
        for (int u = 1; u <= config.players(); u++) inactive[u] = u != self; // until heard
    }

    /**
     * One cycle: {@code cycle} is the perception's cycle number ({@link TimeSlices#cycleOf}),
     * {@code playMode} its play mode (null if absent), {@code heard} its hear perceptors.
     */
    public ChannelOutput step(long cycle, PlayMode playMode, List<Hear> heard) {
        List<ChannelEvent> events = null;
        if (initDeadline == NONE) initDeadline = cycle + config.initTimeoutCycles();
        if (playMode != null && mode != null && playMode != mode) {
            slices = slices.restartedAt(cycle);
            if (phase == Phase.REPORTS || phase == Phase.DISPATCH) events = add(events, new ChannelEvent.RoundAborted(round, cycle));
            if (phase != Phase.INIT) phase = Phase.STARTING;
            pending = List.of();
        }
        if (playMode != null) mode = playMode;

        if (heard != null) {
            for (Hear h : heard) {
                Decoded d = listener.accept(h, cycle);
                if (d != null) events = heardMessage(d, cycle, events);
            }
        }

        String say = null;
        if (phase == Phase.INIT && (allKnown() || cycle >= initDeadline)) phase = Phase.STARTING;
        if (phase == Phase.STARTING && slices.isSlotStart(cycle) && slices.label(cycle) == self) {
            say = codec.encode(new TeamMessage.Start(self), cycle);
            events = beginRound(cycle, cycle + config.startToFirstReportCycles(), events);
        }
        if (phase == Phase.PAUSE && cycle >= nextRoundFirstReport) {
            events = beginRound(nextRoundFirstReport, nextRoundFirstReport, events);
        }
        if (phase == Phase.REPORTS) {
            long lastSlot = firstReport + (long) (config.fieldPlayers() - 1) * config.slotCycles();
            if (cycle >= lastSlot + config.minLatencyCycles() && (allActiveReported() || cycle >= lastSlot + config.maxLatencyCycles())) {
                events = closeReports(cycle, events);
            }
        }
        if (phase == Phase.DISPATCH && say == null && cycle >= nextSay) {
            TeamMessage m = pending.get(pendingIndex++);
            say = codec.encode(m, cycle);
            nextSay = cycle + config.slotCycles();
            if (pendingIndex == pending.size()) {
                nextRoundFirstReport = cycle + (long) config.slotCycles() * (1 + config.pauseSlots());
                phase = Phase.PAUSE;
                events = add(events, new ChannelEvent.ActionsDispatched(round, cycle, pending.size(), pendingActions));
            }
        }
        if (say == null && events == null) return ChannelOutput.NOTHING;
        return new ChannelOutput(say, events);
    }

    private List<ChannelEvent> heardMessage(Decoded d, long cycle, List<ChannelEvent> events) {
        int u;
        if (d.message() instanceof TeamMessage.Init init) {
            u = init.sender();
        } else if (d.message() instanceof TeamMessage.Report r) {
            u = r.sender();
        } else {
            return events; // another coordinator's message: not ours to follow
        }
        if (u < 1 || u > config.players() || u == self) return events;
        if (!known[u] || inactive[u]) {
            known[u] = true;
            inactive[u] = false;
            missed[u] = 0;
            events = add(events, new ChannelEvent.PlayerJoined(u, cycle));
        }
        if (d.message() instanceof TeamMessage.Report r) events = add(events, new ChannelEvent.ReportHeard(r, d.saidCycle(), cycle));
        if (d.message() instanceof TeamMessage.Report r && phase == Phase.REPORTS
                && d.saidCycle() == firstReport + (long) config.reportSlot(u) * config.slotCycles()) {
            reports[u] = r;
        }
        return events;
    }

    private List<ChannelEvent> beginRound(long startCycle, long first, List<ChannelEvent> events) {
        round++;
        firstReport = first;
        java.util.Arrays.fill(reports, null);
        phase = Phase.REPORTS;
        return add(events, new ChannelEvent.RoundStarted(round, startCycle));
    }

    private List<ChannelEvent> closeReports(long cycle, List<ChannelEvent> events) {
        Map<Integer, TeamMessage.Report> heard = new HashMap<>();
        List<Integer> missing = new ArrayList<>();
        Set<Integer> inactiveNow = new HashSet<>();
        for (int u = 1; u <= config.players(); u++) {
            if (u == self) continue;
            if (reports[u] != null) {
                heard.put(u, reports[u]);
                missed[u] = 0;
            } else {
                missing.add(u);
                if (!inactive[u] && ++missed[u] >= config.inactiveAfterMissedRounds()) {
                    inactive[u] = true;
                    events = add(events, new ChannelEvent.PlayerInactive(u, cycle));
                }
            }
            if (inactive[u]) inactiveNow.add(u);
        }
        events = add(events, new ChannelEvent.ReportsComplete(round, cycle, heard.size(), missing));
        List<Action> actions;
        try {
            actions = procedure.actions(new RoundReports(round, cycle, heard, inactiveNow));
            if (actions == null) actions = List.of();
            pending = new ArrayList<>(codec.packActions(actions));
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "coordination procedure failed in round " + round + ", no actions sent: " + e, e);
            actions = List.of();
            pending = List.of();
        }
        if (pending.isEmpty()) pending = List.of(new TeamMessage.End(self));
        pendingIndex = 0;
        pendingActions = actions.size();
        nextSay = cycle + config.computeCycles();
        phase = Phase.DISPATCH;
        return events;
    }

    private boolean allKnown() {
        for (int u = 1; u <= config.players(); u++) if (u != self && !known[u]) return false;
        return true;
    }

    private boolean allActiveReported() {
        for (int u = 1; u <= config.players(); u++) if (u != self && !inactive[u] && reports[u] == null) return false;
        return true;
    }

    private static List<ChannelEvent> add(List<ChannelEvent> events, ChannelEvent e) {
        if (events == null) events = new ArrayList<>(2);
        events.add(e);
        return events;
    }

    public Phase phase() { return phase; }

    public int round() { return round; }

    /** How many heard texts were dropped for this reason so far. */
    public long rejected(Rejection reason) { return listener.rejected(reason); }
}

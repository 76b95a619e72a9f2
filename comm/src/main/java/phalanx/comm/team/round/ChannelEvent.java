package phalanx.comm.team.round;

import phalanx.comm.team.Action;
import phalanx.comm.team.TeamMessage;
import java.util.List;

/** What happened on the team channel in one step, for the agent and the logs (one line each). */
public sealed interface ChannelEvent {
    long cycle();

    /** CoordinatorRounds: a field player announced itself, or came back after being inactive. */
    record PlayerJoined(int unum, long cycle) implements ChannelEvent {
    }

    /** CoordinatorRounds: a field player missed its reports too many rounds in a row. */
    record PlayerInactive(int unum, long cycle) implements ChannelEvent {
    }

    /** CoordinatorRounds: a round began (its start message was said, or its first report slot came). */
    record RoundStarted(int round, long cycle) implements ChannelEvent {
    }

    /** CoordinatorRounds: the report phase closed, with these players' reports missing. */
    record ReportsComplete(int round, long cycle, int heard, List<Integer> missing) implements ChannelEvent {
    }

    /** CoordinatorRounds: the last action message (or the end message) of the round was said. */
    record ActionsDispatched(int round, long cycle, int messages, int actions) implements ChannelEvent {
    }

    /** CoordinatorRounds: the play mode changed mid-round; the round is dropped and a new one starts. */
    record RoundAborted(int round, long cycle) implements ChannelEvent {
    }

    /**
     * Both: a teammate's report was heard (said in {@code saidCycle}). Every player hears the others' reports; a
     * field player uses their ball when it has lost its own (issue 19).
     */
    record ReportHeard(TeamMessage.Report report, long saidCycle, long cycle) implements ChannelEvent {
    }

    /** Field player: the coordinator assigned this action; execute it until the next one. */
    record ActionReceived(Action action, long cycle) implements ChannelEvent {
    }

    /** Field player: the coordinator is heard (again); its actions lead from now on. */
    record Coordinated(long cycle) implements ChannelEvent {
    }

    /** Field player: the coordinator has been quiet too long; act on your own beliefs. */
    record CoordinatorSilent(long cycle) implements ChannelEvent {
    }
}

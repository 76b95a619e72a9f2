package phalanx.comm.team.round;

import phalanx.comm.team.TeamMessage;
import java.util.Map;
import java.util.Set;

/**
 * What the coordinator gathered in one round: the reports heard, by sender, and the field players it
 * counts as inactive (no report for several rounds, or never heard). A player missing from both did
 * not report this round only. The coordinator's own beliefs are not here: the agent adds them.
 */
public record RoundReports(int round, long cycle, Map<Integer, TeamMessage.Report> reports, Set<Integer> inactive) {
    public RoundReports {
        reports = Map.copyOf(reports);
        inactive = Set.copyOf(inactive);
    }
}

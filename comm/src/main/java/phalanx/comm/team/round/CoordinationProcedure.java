package phalanx.comm.team.round;

import phalanx.comm.team.Action;
import java.util.List;

/**
 * The team coordination of thesis 5.1 (Algorithm 3), as the team channel sees it: the reports of a
 * round in, one action per field player out. The coordination module provides it; the coordinator
 * calls it in the cycle the report phase closes and sends what it returns. A player left out keeps
 * executing its previous action (5.3). Must not return two actions for one player.
 */
@FunctionalInterface
public interface CoordinationProcedure {
    List<Action> actions(RoundReports reports);
}

package phalanx.agent;

import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.goalkeeper.GoalkeeperBehaviour;
import phalanx.agent.team.TeamChannel;

/** Player 1: the goalkeeper's behaviour of thesis 5.13 (the coordinator runs in its team channel). */
final class GoalkeeperBrain implements Brain {
    private final GoalkeeperBehaviour keeper;

    GoalkeeperBrain(GoalkeeperBehaviour keeper) { this.keeper = keeper; }

    @Override public Decision decide(Situation s, TeamChannel channel) { return keeper.decide(s); }

    boolean hasBall() { return keeper.hasBall(); }
}

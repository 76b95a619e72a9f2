package phalanx.agent;

import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.agent.team.TeamChannel;

/**
 * Stands and scans with the head (±60° over 4 s) so that localization sees landmarks. Used until the
 * behaviours of thesis 4.6 and 5.13 are wired in; also a safe brain for tests of the loop.
 */
final class InterimBrain implements Brain {
    @Override public Decision decide(Situation s, TeamChannel channel) {
        double yaw = 60 * Math.sin(2 * Math.PI * s.now() / 4.0);
        return Decision.of(Move.STAND, new HeadTarget(yaw, 0));
    }
}

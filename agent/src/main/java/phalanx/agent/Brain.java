package phalanx.agent;

import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.team.TeamChannel;

/** The deciding part of a player: the goalkeeper's or a field player's behaviour. */
public interface Brain {
    Decision decide(Situation s, TeamChannel channel);

    /** Where the brain is heading, for debug drawing (own frame); null when it has no target. */
    default phalanx.model.field.Vector2 target() { return null; }
}

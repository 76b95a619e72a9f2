package phalanx.agent.action;

import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * A head-only basic action (4.6.1: Look Straight, Pan Head, Scan, Track Object). Alone it stands;
 * complex actions take its {@link #head} and add their own move.
 */
public interface HeadControl extends Action {
    HeadTarget head(Situation s);

    @Override
    default Decision decide(Situation s) { return Decision.of(Move.STAND, head(s)); }
}

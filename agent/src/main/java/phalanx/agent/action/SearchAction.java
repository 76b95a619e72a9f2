package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * The shape the searching actions of 4.6.1 share (Find Opponent's Goal, Look For Ball, Turn To
 * Localize): while not {@link #done}, a move of their own with the head sweeping; once done, what they
 * do with what they found.
 */
abstract class SearchAction implements Action {
    protected final AgentConfig config;
    /** The head's sweep while searching (Scan or Pan Head). */
    protected final HeadControl sweep;

    SearchAction(AgentConfig config, HeadControl sweep) {
        this.config = config;
        this.sweep = sweep;
    }

    @Override
    public final Decision decide(Situation s) {
        return done(s) ? found(s) : Decision.of(searching(s), sweep.head(s));
    }

    /** The body's move while searching. */
    protected abstract Move searching(Situation s);

    /** The decision once the search is done. */
    protected abstract Decision found(Situation s);
}

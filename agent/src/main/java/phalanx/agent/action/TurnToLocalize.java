package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * 4.6.1 Turn To Localize: turn the body (left, full gain) while panning the head until the self
 * belief is fresh and confident again.
 */
public final class TurnToLocalize implements Action {
    private final AgentConfig config;
    private final PanHead pan;

    public TurnToLocalize(AgentConfig config) {
        this.config = config;
        this.pan = new PanHead(config);
    }

    @Override
    public Decision decide(Situation s) {
        if (done(s)) return Decision.of(Move.STAND, pan.head(s));
        return Decision.of(new Move.Turn(true, config.walk().gainMax()), pan.head(s));
    }

    @Override
    public boolean done(Situation s) { return Facts.selfLocalized(s, config); }
}

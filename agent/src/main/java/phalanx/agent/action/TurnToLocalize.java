package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * 4.6.1 Turn To Localize: turn the body (left, full gain) while panning the head until the self
 * belief is fresh and confident again.
 */
public final class TurnToLocalize extends SearchAction {

    public TurnToLocalize(AgentConfig config) { super(config, new PanHead(config)); }

    @Override
    protected Move searching(Situation s) { return new Move.Turn(true, config.walk().gainMax()); }

    @Override
    protected Decision found(Situation s) { return Decision.of(Move.STAND, sweep.head(s)); }

    @Override
    public boolean done(Situation s) { return Facts.selfLocalized(s, config); }
}

package phalanx.agent.goalkeeper;

import phalanx.agent.AgentConfig;
import phalanx.agent.action.OneShot;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;

/**
 * The goalkeeper's fall to one side (5.13, Figure 5.16), played once: requested until it shows as
 * playing, then left to play out (see {@link OneShot}).
 */
final class Dive implements Action {
    private final OneShot play;
    private boolean left;

    Dive(AgentConfig config) { this.play = new OneShot(config.kick().oneShotTimeout()); }

    void start(Situation s, boolean toLeft) {
        left = toLeft;
        play.start(s);
    }

    @Override
    public Decision decide(Situation s) {
        if (!play.active() || play.finished(s)) return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
        return Decision.of(play.requesting() ? new Move.Dive(left) : Move.STAND, HeadTarget.STRAIGHT);
    }

    @Override
    public boolean done(Situation s) { return !play.active(); }
}

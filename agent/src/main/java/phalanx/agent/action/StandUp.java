package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.localization.fall.FallState;

/**
 * 4.6.1 Stand Up: after a confirmed fall (the belief store's FALLEN_FRONT / FALLEN_BACK) play the
 * matching stand-up motion to its end, then look again: still down, play it again ("repeated until
 * it succeeds"). While only FALLING (not confirmed; a collision looks the same) it waits.
 * Unlike a kick, the get-up stays requested for its whole play: the files begin with a one-cycle
 * {@code Begin} phase whose finalize leads to {@code Done} (motions/README.md), so a get-up nobody
 * requests any more leaves after that cycle. Requesting it only until it showed as playing (as kicks
 * are) ended every get-up after 20 ms: in a game against FC Portugal our players lay until the next
 * goal's beam (183 falls in 600 s, none stood up by itself).
 */
public final class StandUp implements Action {
    private final OneShot play;
    private boolean fromFront;

    public StandUp(AgentConfig config) { this.play = new OneShot(config.kick().oneShotTimeout()); }

    @Override
    public Decision decide(Situation s) {
        if (play.active() && !play.finished(s)) return Decision.of(new Move.StandUp(fromFront), HeadTarget.STRAIGHT);
        FallState f = Facts.fall(s);
        if (f.isDown()) {
            fromFront = f == FallState.FALLEN_FRONT;
            play.start(s);
            return Decision.of(new Move.StandUp(fromFront), HeadTarget.STRAIGHT);
        }
        return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
    }

    /** Standing, and no stand-up motion is still playing. */
    @Override
    public boolean done(Situation s) { return Facts.fall(s) == FallState.STANDING && !play.active(); }

    /** True while a stand-up motion is requested or playing. */
    public boolean busy() { return play.active(); }
}

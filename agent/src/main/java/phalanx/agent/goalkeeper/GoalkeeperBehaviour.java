package phalanx.agent.goalkeeper;

import phalanx.agent.AgentConfig;
import phalanx.agent.action.Facts;
import phalanx.agent.action.StandUp;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.PlayMode;
import phalanx.localization.fall.FallState;

/**
 * Player 1's decisions each cycle: stand up first whenever down (but never in the middle of a
 * dive: the keeper lies on purpose), wait while only falling, stand still once the game is over,
 * otherwise the goalkeeper state machine. The coordinator runs beside it on the same player;
 * {@link #hasBall()} tells it to switch to Support mode.
 */
public final class GoalkeeperBehaviour {
    private final Goalkeeper keeper;
    private final StandUp standUp;

    public GoalkeeperBehaviour(AgentConfig config) {
        this.keeper = new Goalkeeper(config);
        this.standUp = new StandUp(config);
    }

    public Decision decide(Situation s) {
        if (keeper.diving()) return keeper.decide(s);
        FallState f = Facts.fall(s);
        if (f.isDown() || standUp.busy()) return standUp.decide(s);
        if (f == FallState.FALLING) return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
        if (s.playMode() == PlayMode.GAME_OVER) return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
        return keeper.decide(s);
    }

    public Goalkeeper.State state() { return keeper.state(); }

    /** The goalkeeper is clearing the ball (Libero): coordination's goalkeeperHasBall. */
    public boolean hasBall() { return keeper.hasBall(); }
}

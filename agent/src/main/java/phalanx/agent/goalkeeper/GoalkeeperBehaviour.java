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
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * Player 1's decisions each cycle: stand up first whenever down (but never in the middle of a
 * dive: the keeper lies on purpose), wait while only falling, stand still once the game is over,
 * otherwise the goalkeeper state machine. The coordinator runs beside it on the same player;
 * {@link #hasBall()} tells it to switch to Support mode.
 */
public final class GoalkeeperBehaviour {
    private static final Logger LOG = Logger.getLogger(GoalkeeperBehaviour.class.getName());
    private final AgentConfig config;
    private final Goalkeeper keeper;
    private final StandUp standUp;
    private Goalkeeper.State lastState;
    private FallState lastFall;

    public GoalkeeperBehaviour(AgentConfig config) {
        this.config = config;
        this.keeper = new Goalkeeper(config);
        this.standUp = new StandUp(config);
    }

    public Decision decide(Situation s) {
        Decision d = decideNow(s);
        logPhase(s);
        return d;
    }

    /** One log line whenever the keeper's state or fall state changes: what a match review needs (rare events). */
    private void logPhase(Situation s) {
        FallState f = Facts.fall(s);
        if (keeper.state() == lastState && f == lastFall) return;     // no string built in an ordinary cycle
        lastState = keeper.state();
        lastFall = f;
        String phase = lastState + (f == FallState.STANDING ? "" : " " + f);
        Pose2 self = Facts.self(s, config);
        Vector2 ball = Facts.ballGlobal(s, config);
        LOG.info(String.format(Locale.ROOT, "keeper %s at game time %.2f self=%s ball=%s", phase, s.gameTime(),
                self == null ? "?" : String.format(Locale.ROOT, "(%.2f,%.2f,%.0f)", self.x(), self.y(), self.thetaDeg()),
                ball == null ? "?" : String.format(Locale.ROOT, "(%.2f,%.2f)", ball.x(), ball.y())));
    }

    private Decision decideNow(Situation s) {
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

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

/** Our kick-off: the taker taps, the partner plays the ball, and both go back to the usual choice after. */
class KickOffPlayTest {
    private static final AgentConfig C = AgentConfig.DEFAULT.withKickOff(AgentConfig.KickOff.TAP);
    private static final int TAKER = C.kickOff().taker(), PARTNER = C.kickOff().partner();

    /** A left-side player at (x, y) facing the goal, the ball on the centre spot, at game time t. */
    private static World at(double x, double y, PlayMode mode, double t) {
        World w = World.at(x, y, 0).time(t).ballAt(0, 0);
        w.mode = mode;
        return w;
    }

    @Test
    void inOurKickOffTheTakerWalksToTheBallThenStepsSlowlyIntoItAndThePartnerWaits() {
        KickOffPlay taker = new KickOffPlay(C, TAKER), partner = new KickOffPlay(C, PARTNER);
        assertEquals(KickOffPlay.Part.TAKER, taker.part());
        Decision far = taker.decide(at(-0.64, 0, PlayMode.KICK_OFF_LEFT, 0.1).situation());
        assertNotNull(far);
        assertNotEquals(Move.STAND, far.move(), "0.64 m away it walks to the ball");
        Decision near = taker.decide(at(-0.2, 0.05, PlayMode.KICK_OFF_LEFT, 2).situation());
        assertEquals(new Move.Walk(0, true), near.move(), "at the ball: slow forward steps, the tap");
        assertEquals(Move.STAND, partner.decide(at(-0.55, -0.45, PlayMode.KICK_OFF_LEFT, 2).situation()).move());
    }

    @Test
    void theirKickOffAndEveryOtherPlayerAreLeftToTheUsualChoice() {
        assertNull(new KickOffPlay(C, TAKER).decide(at(-0.64, 0, PlayMode.KICK_OFF_RIGHT, 1).situation()));
        assertNull(new KickOffPlay(C, 7).decide(at(-0.64, 0, PlayMode.KICK_OFF_LEFT, 1).situation()));
        assertNull(new KickOffPlay(C.withKickOff(AgentConfig.KickOff.OFF), TAKER)
                .decide(at(-0.64, 0, PlayMode.KICK_OFF_LEFT, 1).situation()));
        assertNull(new KickOffPlay(C, TAKER).decide(at(-0.2, 0, PlayMode.PLAY_ON, 1).situation()),
                "PlayOn that did not follow our kick-off is ordinary play");
    }

    @Test
    void afterTheTapTheTakerLeavesTheBallUntilTheHoldEnds() {
        KickOffPlay taker = new KickOffPlay(C, TAKER);
        taker.decide(at(-0.2, 0.05, PlayMode.KICK_OFF_LEFT, 3.0).situation());
        Decision d = taker.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02).situation());
        assertEquals(Move.STAND, d.move(), "the ball at its feet, but a second touch is a foul");
        assertTrue(taker.holding());
        assertEquals(Move.STAND, taker.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02 + C.kickOff().holdSeconds() - 0.1).situation()).move());
        assertNull(taker.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02 + C.kickOff().holdSeconds() + 0.1).situation()));
        assertFalse(taker.holding());
    }

    @Test
    void theHoldEndsAsSoonAsTheBallIsAwayFromTheCentreSpot() {
        KickOffPlay taker = new KickOffPlay(C, TAKER);
        taker.decide(at(-0.2, 0.05, PlayMode.KICK_OFF_LEFT, 3.0).situation());
        taker.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02).situation());
        World moved = World.at(-0.2, 0.05, 0).time(4).ballAt(3, 1);   // the partner's kick
        assertNull(new KickOffPlay(C, 7).decide(moved.situation()));
        assertNull(taker.decide(moved.situation()));
        assertFalse(taker.holding());
    }

    @Test
    void afterTheTapThePartnerPlaysTheBallWithOnBall() {
        KickOffPlay partner = new KickOffPlay(C, PARTNER);
        partner.decide(at(-0.55, -0.45, PlayMode.KICK_OFF_LEFT, 3.0).situation());
        Decision d = partner.decide(at(-0.55, -0.45, PlayMode.PLAY_ON, 3.02).situation());
        assertNotNull(d);
        assertNotEquals(Move.STAND, d.move(), "0.7 m from the ball it goes to it");
        assertTrue(partner.holding());
    }

    @Test
    void theTakersOrdersWaitWhileItHolds() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C, TAKER);
        Vector2 home = new Vector2(-1, 0);
        b.decide(at(-0.2, 0.05, PlayMode.KICK_OFF_LEFT, 3.0).situation(), true, home);
        b.order(Action.of(TAKER, ActionId.ON_BALL));   // the coordinator sends the nearest player to the ball
        assertEquals(Move.STAND, b.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02).situation(), false, home).move());
        Decision later = b.decide(at(-0.2, 0.05, PlayMode.PLAY_ON, 3.02 + C.kickOff().holdSeconds() + 0.1).situation(), false, home);
        assertTrue(b.running() instanceof OnBall, "after the hold the order runs: " + later);
    }
}

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.comm.perception.PlayMode;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

/** We play on the left (own frame, own goal at x = -15); the referee clears 2 m round the ball at their set pieces. */
class TheirSetPieceTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;

    private static World in(PlayMode m, double x, double y, double ballX, double ballY) {
        World w = World.at(x, y, 0).ballAt(ballX, ballY);
        w.mode = m;
        return w;
    }

    private static Pose2 target(Action a) {
        assertInstanceOf(WalkToCoordinate.class, a);
        return ((WalkToCoordinate) a).target();
    }

    @Test
    void atTheirKickOffAPlayerGoingToTheBallStandsOnTheBallsLineToOurGoalOutsideTheCircle() {
        // Session 20's g4: our player 10 walked at the ball at their kick-off and was moved away twice, falling each time.
        TheirSetPiece t = new TheirSetPiece(C);
        OnBall onBall = new OnBall(C);
        Pose2 p = target(t.adjust(in(PlayMode.KICK_OFF_RIGHT, -1.5, 0.5, 0, 0).situation(), onBall));
        assertEquals(-2.6, p.x(), 1e-9);
        assertEquals(0, p.y(), 1e-9);
        assertEquals(0, p.thetaDeg(), 1e-9, "faces the ball");
        // Our own kick-off and play on leave the action alone.
        assertSame(onBall, t.adjust(in(PlayMode.KICK_OFF_LEFT, -1.5, 0.5, 0, 0).situation(), onBall));
        assertSame(onBall, t.adjust(in(PlayMode.PLAY_ON, -1.5, 0.5, 0, 0).situation(), onBall));
        // Switched off: alone too.
        assertSame(onBall, new TheirSetPiece(C.withSetPieces(AgentConfig.SetPieces.OFF))
                .adjust(in(PlayMode.KICK_OFF_RIGHT, -1.5, 0.5, 0, 0).situation(), onBall));
    }

    @Test
    void aWalkToAPointTheRefereeClearsGoesToTheNearestPointItDoesNot() {
        TheirSetPiece t = new TheirSetPiece(C);
        // Their kick-off: a spot in their half and in the circle is moved into our half, then out of the circle.
        WalkToCoordinate toCentre = new WalkToCoordinate(C, 0.5, 1, 0);
        Pose2 p = target(t.adjust(in(PlayMode.KICK_OFF_RIGHT, -4, 1, 0, 0).situation(), toCentre));
        assertTrue(p.x() <= -0.3, "in our half: " + p);
        assertTrue(Math.hypot(p.x(), p.y()) >= 2.6 - 1e-9, "outside the circle: " + p);
        // A spot that is allowed, walked to from a place that is allowed: the same action.
        WalkToCoordinate fine = new WalkToCoordinate(C, -5, 2, 0);
        assertSame(fine, t.adjust(in(PlayMode.KICK_OFF_RIGHT, -4, 1, 0, 0).situation(), fine));
        // Their free kick at (-5, 3): a player standing 1 m from the ball is sent out radially to 2.6 m.
        Pose2 q = target(t.adjust(in(PlayMode.FREE_KICK_RIGHT, -6, 3, -5, 3).situation(), new WalkToCoordinate(C, -6, 3, 0)));
        assertEquals(-7.6, q.x(), 1e-9);
        assertEquals(3, q.y(), 1e-9);
        // Their goal kick: a spot inside their penalty area (x >= 13.2) is moved out of it with the margin.
        Pose2 g = target(t.adjust(in(PlayMode.GOAL_KICK_RIGHT, 10, 0, 14, 1).situation(), new WalkToCoordinate(C, 13.5, -1, 0)));
        assertTrue(g.x() <= 15 - 1.8 - 0.3, "out of their area: " + g);
        assertTrue(new Vector2(g.x(), g.y()).distanceTo(new Vector2(14, 1)) >= 2.6 - 1e-9, g.toString());
    }

    @Test
    void whoseSetPieceItIs() {
        assertTrue(TheirSetPiece.theirs(in(PlayMode.KICK_IN_RIGHT, 0, 0, 0, 0).situation()));
        assertTrue(TheirSetPiece.theirs(in(PlayMode.CORNER_KICK_RIGHT, 0, 0, 0, 0).situation()));
        assertTrue(TheirSetPiece.theirs(in(PlayMode.OFFSIDE_LEFT, 0, 0, 0, 0).situation()), "our offside: their free kick");
        assertFalse(TheirSetPiece.theirs(in(PlayMode.OFFSIDE_RIGHT, 0, 0, 0, 0).situation()));
        assertFalse(TheirSetPiece.theirs(in(PlayMode.FREE_KICK_LEFT, 0, 0, 0, 0).situation()));
        assertFalse(TheirSetPiece.theirs(in(PlayMode.GOAL_RIGHT, 0, 0, 0, 0).situation()), "a goal is nobody's set piece");
        assertFalse(TheirSetPiece.theirs(in(PlayMode.BEFORE_KICK_OFF, 0, 0, 0, 0).situation()));
    }

    @Test
    void theFieldPlayerKeepsOutAtTheirKickOffEvenWhenItsOwnChoiceIsTheBall() {
        // The coordinator quiet, the ball 1.6 m away and nobody nearer: the fallback's own choice is On Ball, but at their
        // kick-off the player walks away from the ball to the circle's outside instead of at it.
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        World w = in(PlayMode.KICK_OFF_RIGHT, -1.5, 0.5, 0, 0);
        var d = b.decide(w.situation(), true, new Vector2(-3, 0));
        assertInstanceOf(OnBall.class, b.running(), "its own choice is still On Ball");
        // (-2.6, 0) lies behind it, 155 deg to its right: it turns round first.
        assertEquals(new phalanx.agent.decide.Move.Turn(false, 1.0), d.move());
    }
}

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;
import phalanx.model.field.Pose2;

import static org.junit.jupiter.api.Assertions.*;

/** On Ball's approach to the spot behind the ball (ours); the opponent goal is at (15, 0). */
class ApproachBallTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;
    private final ApproachBall a = new ApproachBall(C);

    @Test
    void fromBehindItHeadsForTheSpotBehindTheBallAtFullSpeed() {
        var s = World.at(-5, 0, 0).ballAt(0, 0).situation();
        Pose2 t = a.target(s);
        // 0.22 m behind the ball on the goal line, and 0.055 m left of it so the ball lies before the right foot
        assertEquals(-0.22, t.x(), 1e-9);
        assertEquals(0.055, t.y(), 1e-9);
        assertEquals(0, t.thetaDeg(), 1e-9);
        Move.Omni m = (Move.Omni) a.decide(s).move();
        assertEquals(1.0, m.forward(), 1e-3);
        // the walk goes where the spot is: shares times the walk's limits (0.88 forward, 0.1 sideways) point at it
        assertEquals(0.055 / 4.78, m.left() * 0.1 / (m.forward() * 0.88), 1e-6);
        assertFalse(a.done(s));
    }

    @Test
    void besideThePostOnTheGoalLineItLinesUpOnTheGoalMouthNotItsCentre() {
        // The centre is 82 degrees from here and the far post 85.7: a kick at the centre skims along the line.
        var s = World.at(13, -3, 45).ballAt(14.85, -1.11).situation();
        double heading = a.target(s).thetaDeg();
        assertEquals(Facts.goalAim(s, new phalanx.model.field.Vector2(14.85, -1.11)).minus(new phalanx.model.field.Vector2(14.85, -1.11)).angleDeg(),
                heading, 1e-9);
        assertEquals(70.1, heading, 0.5, "the bisector of the posts (brought in 0.15 m) from the ball");
    }

    @Test
    void fromTheGoalSideItGoesRoundTheBallNotThroughIt() {
        var s = World.at(1.0, 0.1, 180).ballAt(0, 0).situation();   // between the ball and the goal, facing the ball
        Pose2 t = a.target(s);
        assertEquals(-0.22, t.x(), 1e-9);
        assertEquals(0.45, t.y(), 1e-9, "the point beside the ball on the robot's side");
        var below = World.at(1.0, -0.1, 180).ballAt(0, 0).situation();
        assertEquals(-0.45, a.target(below).y(), 1e-9);
    }

    @Test
    void atTheSpotFacingTheGoalItIsDoneAndTurnedAwayItTurnsBack() {
        assertTrue(a.done(World.at(-0.22, 0.055, 3).ballAt(0, 0).situation()));
        var turned = World.at(-0.22, 0.055, 30).ballAt(0, 0).situation();
        assertFalse(a.done(turned));
        Move.Omni m = (Move.Omni) a.decide(turned).move();
        assertEquals(-1.0, m.turn(), 1e-9, "30 degrees left of the goal: full turn to the right");
        assertEquals(0, m.forward(), 1e-9);
    }

    @Test
    void facingAwayFromAFarSpotItTurnsBeforeItWalks() {
        Move.Omni m = (Move.Omni) a.decide(World.at(-5, 0, 180).ballAt(0, 0).situation()).move();
        assertEquals(1.0, Math.abs(m.turn()), 1e-9);
        assertTrue(Math.max(Math.abs(m.forward()), Math.abs(m.left())) <= 0.2 + 1e-9, m.toString());
    }

    @Test
    void nearTheSpotASidewaysErrorIsWalkedAtTheSidewaysLimit() {
        // 6 cm right of the spot, facing the goal: all sideways, at the full share the distance allows
        Move.Omni m = (Move.Omni) a.decide(World.at(-0.22, 0.115, 0).ballAt(0, 0).situation()).move();
        assertEquals(0, m.forward(), 1e-9);
        assertEquals(-C.approach().minShare(), m.left(), 1e-9, "0.06 m within slowWithin: the minimum share, to the right");
    }

    @Test
    void withoutASelfPoseThereIsNoApproachAndOnBallWalksAsTheThesisDoes() {
        var lost = World.lost().ballRel(2, 0).situation();
        assertFalse(a.usable(lost));
        assertInstanceOf(Move.Walk.class, new OnBall(C).decide(lost).move());
        assertInstanceOf(Move.Omni.class, new OnBall(C).decide(World.at(-5, 0, 0).ballAt(0, 0).situation()).move());
    }

    @Test
    void aStaleSelfBeliefIsNoGroundToSteerBy() {
        World w = World.at(-5, 0, 0).ballAt(0, 0);
        assertTrue(a.usable(w.situation()));
        w.selfAge = 2;   // seconds since the last fix: the pose is odometry only
        assertFalse(a.usable(w.situation()));
        assertInstanceOf(Move.Walk.class, new OnBall(C).decide(w.situation()).move(), "the thesis's Walk To Ball instead");
    }

    @Test
    void omniSharesAreClampedAndABadNumberStopsThatPart() {
        Move.Omni m = new Move.Omni(2, Double.NaN, -3);
        assertEquals(1, m.forward());
        assertEquals(0, m.left());
        assertEquals(-1, m.turn());
    }
}

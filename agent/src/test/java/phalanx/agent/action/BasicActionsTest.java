package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.localization.fall.FallState;

import static org.junit.jupiter.api.Assertions.*;

class BasicActionsTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;

    @Test
    void turnToBallTurnsTowardTheBallsSide() {
        TurnToBall t = new TurnToBall(C);
        Move left = t.decide(World.at(0, 0, 0).ballRel(1, 1).situation()).move();
        Move right = t.decide(World.at(0, 0, 0).ballRel(1, -1).situation()).move();
        assertTrue(left instanceof Move.Turn l && l.left(), "ball to the left: " + left);
        assertTrue(right instanceof Move.Turn r && !r.left(), "ball to the right: " + right);
    }

    @Test
    void turnToBallGainGrowsWithTheAngleWithinTheThesisRange() {
        TurnToBall t = new TurnToBall(C);
        // Figure 4.10: gain 0.3 turns 7°, 1.0 turns 40°; 20° lies between.
        double small = ((Move.Turn) t.decide(World.at(0, 0, 0).ballRel(1, Math.tan(Math.toRadians(12))).situation()).move()).gain();
        double mid = ((Move.Turn) t.decide(World.at(0, 0, 0).ballRel(1, Math.tan(Math.toRadians(20))).situation()).move()).gain();
        double big = ((Move.Turn) t.decide(World.at(0, 0, 0).ballRel(0, 1).situation()).move()).gain();
        assertEquals(0.3 + 0.7 * 13 / 33, mid, 1e-9);
        assertTrue(small < mid && mid < big);
        assertEquals(1.0, big);
    }

    @Test
    void turnToBallIsDoneWhenFacingIt() {
        TurnToBall t = new TurnToBall(C);
        var s = World.at(0, 0, 0).ballRel(2, 0.2).situation();     // 5.7°
        assertTrue(t.done(s));
        assertEquals(Move.STAND, t.decide(s).move());
        assertFalse(t.done(World.at(0, 0, 0).situation()), "no ball: not done");
    }

    @Test
    void lookForBallTurnsTowardWhereTheBallWasLastSeen() {
        LookForBall l = new LookForBall(C);
        Move never = l.decide(World.at(0, 0, 0).situation()).move();
        assertTrue(never instanceof Move.Turn t && t.left());
        World old = World.at(0, 0, 0).ballRel(1, -2);
        old.ballAge = 5;                                         // seen long ago on the right
        Move right = l.decide(old.situation()).move();
        assertTrue(right instanceof Move.Turn t && !t.left());
        var inView = World.at(0, 0, 0).ballRel(3, 0).situation();
        assertTrue(l.done(inView));
        assertEquals(Move.STAND, l.decide(inView).move());
    }

    @Test
    void turnToLocalizeTurnsUntilTheSelfBeliefIsFreshAndConfident() {
        TurnToLocalize t = new TurnToLocalize(C);
        World stale = World.at(1, 1, 0);
        stale.selfAge = 2;
        assertTrue(t.decide(stale.situation()).move() instanceof Move.Turn);
        World unsure = World.at(1, 1, 0);
        unsure.confidence = 0.2;
        assertFalse(t.done(unsure.situation()));
        assertTrue(t.decide(World.lost().situation()).move() instanceof Move.Turn);
        assertTrue(t.done(World.at(1, 1, 0).situation()));
        assertEquals(Move.STAND, t.decide(World.at(1, 1, 0).situation()).move());
    }

    @Test
    void findOpponentGoalScansUntilLocalizedThenKnowsTheBearing() {
        FindOpponentGoal f = new FindOpponentGoal(C);
        World stale = World.at(0, 0, 90);
        stale.selfAge = 2;
        assertFalse(f.done(stale.situation()));
        var s = World.at(0, 0, 90).situation();    // facing +y; the goal (15, 0) lies 90° to the right
        assertTrue(f.done(s));
        assertEquals(-90, FindOpponentGoal.goalBearingFrom(s, C, new phalanx.model.field.Vector2(0, 0)), 1e-9);
        // From (0, 5) the aim is the posts' bisector (Facts.goalAim): it meets the line at y = 0.016, not the centre.
        assertEquals(-90 - Math.toDegrees(Math.atan2(5 - 0.01615, 15)),
                FindOpponentGoal.goalBearingFrom(s, C, new phalanx.model.field.Vector2(0, 5)), 1e-4);
    }

    @Test
    void standUpPicksTheMotionForTheSideItLiesOn() {
        assertEquals(new Move.StandUp(true), new StandUp(C).decide(World.at(0, 0, 0).fall(FallState.FALLEN_FRONT).situation()).move());
        assertEquals(new Move.StandUp(false), new StandUp(C).decide(World.at(0, 0, 0).fall(FallState.FALLEN_BACK).situation()).move());
        StandUp falling = new StandUp(C);
        assertEquals(Move.STAND, falling.decide(World.at(0, 0, 0).fall(FallState.FALLING).situation()).move());
        assertFalse(falling.done(World.at(0, 0, 0).fall(FallState.FALLING).situation()));
        assertTrue(new StandUp(C).done(World.at(0, 0, 0).situation()));
    }

    @Test
    void standUpPlaysTheMotionOnceThenRepeatsWhileStillDown() {
        StandUp u = new StandUp(C);
        World w = World.at(0, 0, 0).fall(FallState.FALLEN_BACK);
        assertEquals(new Move.StandUp(false), u.decide(w.time(10).situation()).move());
        // Not playing yet (one cycle of latency): still requested.
        assertEquals(new Move.StandUp(false), u.decide(w.time(10.02).situation()).move());
        // Playing: still requested for its whole play (its Begin phase leaves through Done otherwise).
        w.motion("stand_up_back", null, 0);
        assertEquals(new Move.StandUp(false), u.decide(w.time(10.04).situation()).move());
        w.fall(FallState.FALLING);                                     // rising: still busy
        assertEquals(new Move.StandUp(false), u.decide(w.time(11).situation()).move());
        assertTrue(u.busy());
        // The motion ended with the robot still on its back: once more.
        w.fall(FallState.FALLEN_BACK).motion(null, "stand_up_back", 1);
        assertEquals(new Move.StandUp(false), u.decide(w.time(12.2).situation()).move());
        w.motion("stand_up_back", "stand_up_back", 1);
        u.decide(w.time(12.24).situation());
        w.fall(FallState.STANDING).motion(null, "stand_up_back", 2);
        assertEquals(Move.STAND, u.decide(w.time(14.5).situation()).move());
        assertTrue(u.done(w.situation()));
    }

    @Test
    void prepareForKickUsesSideStepsThenForwardStepsUntilTheBallIsAtTheRightFoot() {
        PrepareForKick p = new PrepareForKick(C);
        assertEquals(new Move.SideStep(true), p.decide(World.at(0, 0, 0).ballRel(0.25, 0.05).situation()).move());
        assertEquals(new Move.SideStep(false), p.decide(World.at(0, 0, 0).ballRel(0.25, -0.12).situation()).move());
        assertEquals(new Move.Walk(0, true), p.decide(World.at(0, 0, 0).ballRel(0.25, -0.06).situation()).move());
        var ready = World.at(0, 0, 0).ballRel(0.18, -0.07).situation();
        assertTrue(p.done(ready));
        assertEquals(Move.STAND, p.decide(ready).move());
        assertFalse(p.done(World.at(0, 0, 0).ballRel(0.21, -0.055).situation()), "4 cm too far");
        assertFalse(p.done(World.at(0, 0, 0).ballRel(0.17, -0.02).situation()), "3.5 cm too far left");
        assertTrue(p.done(World.at(0, 0, 0).ballRel(0.145, -0.055).situation()), "2.5 cm short: inside the band");
    }

    @Test
    void prepareForKickSideStepsAwayFromABallThatStaysCaughtAtItsFeetWhileItStepsBack() {
        PrepareForKick p = new PrepareForKick(C);
        // The ball 8 cm ahead, 6 cm right (the session 24 game): step back ...
        assertEquals(new Move.StepBack(), p.decide(World.at(0, 0, 0).time(100.0).ballRel(0.08, -0.06).situation()).move());
        assertEquals(new Move.StepBack(), p.decide(World.at(0, 0, 0).time(100.9).ballRel(0.08, -0.06).situation()).move());
        // ... and after a second with the ball still there, a side step away from it (left: the ball is right).
        assertEquals(new Move.SideStep(true), p.decide(World.at(0, 0, 0).time(101.1).ballRel(0.09, -0.06).situation()).move());
        // A ball that does come away with the steps is stepped back from as before.
        PrepareForKick q = new PrepareForKick(C);
        q.decide(World.at(0, 0, 0).time(200.0).ballRel(0.05, 0.04).situation());
        assertEquals(new Move.StepBack(), q.decide(World.at(0, 0, 0).time(201.2).ballRel(0.10, 0.04).situation()).move());
        // Once the ball is out of the back band the count starts again.
        q.decide(World.at(0, 0, 0).time(201.3).ballRel(0.25, -0.06).situation());
        assertEquals(new Move.StepBack(), q.decide(World.at(0, 0, 0).time(201.4).ballRel(0.08, 0.04).situation()).move());
        assertEquals(new Move.SideStep(false), q.decide(World.at(0, 0, 0).time(202.5).ballRel(0.08, 0.04).situation()).move());
    }

    @Test
    void prepareForKickTakesTheFootOnTheBallsSideAndItsMirroredSpot() {
        PrepareForKick p = new PrepareForKick(C);
        // Ball 4 cm left of the body's axis when preparing begins: the left foot, whose spot is 0.055 m left.
        p.choose(World.at(0, 0, 0).ballRel(0.25, 0.04).situation(), false);
        assertTrue(p.leftFoot());
        assertEquals(new Move.SideStep(true), p.decide(World.at(0, 0, 0).ballRel(0.25, 0.09).situation()).move(), "3.5 cm too far left: step left");
        assertEquals(new Move.Walk(0, true), p.decide(World.at(0, 0, 0).ballRel(0.25, 0.04).situation()).move(), "in the left band");
        assertTrue(p.done(World.at(0, 0, 0).ballRel(0.17, 0.055).situation()));
        assertFalse(p.done(World.at(0, 0, 0).ballRel(0.17, -0.055).situation()), "the right foot's spot is not the left one's");
        // The choice is kept until the next call: a ball drifting right is stepped after, not switched to.
        assertEquals(new Move.SideStep(false), p.decide(World.at(0, 0, 0).ballRel(0.25, -0.01).situation()).move());
        p.choose(World.at(0, 0, 0).ballRel(0.25, -0.01).situation(), false);
        assertFalse(p.leftFoot());
    }

    @Test
    void theStrongKickIsPreparedForAtItsOwnSpot() {
        AgentConfig.Kick k = C.kick();
        assertNotEquals(k.spotX(false), k.spotX(true), "strong_kick.xml was tuned for another spot than kick.xml");
        PrepareForKick p = new PrepareForKick(C);
        var ball = World.at(0, 0, 0).ballRel(k.spotX(false) - 0.025, k.spotY(false, false)).situation();
        p.choose(ball, false);
        assertTrue(p.done(ball), "inside the normal kick's band");
        p.choose(ball, true);
        assertTrue(p.strong());
        assertFalse(p.done(ball), "short of the strong kick's band");
        assertEquals(new Move.StepBack(), p.decide(ball).move());
        var right = World.at(0, 0, 0).ballRel(k.spotX(true), k.spotY(true, false)).situation();
        assertTrue(p.done(right));
        p.choose(World.at(0, 0, 0).ballRel(0.25, 0.03).situation(), true);
        assertTrue(p.leftFoot() && p.done(World.at(0, 0, 0).ballRel(k.spotX(true), -k.spotY(true, false)).situation()), "the left foot's mirrored strong spot");
    }

    @Test
    void prepareForKickStepsOnUntilTheBallIsNearTheSpotNotJustInsideTheBand() {
        // In a game the robot stopped where it first accepted the ball: 2.5 cm beyond the strong spot, where the
        // strong kick goes 8 m instead of 10 (motion/README.md, session 7).
        AgentConfig.Kick k = C.kick();
        PrepareForKick p = new PrepareForKick(C);
        var far = World.at(0, 0, 0).ballRel(k.spotX(true) + 0.025, k.spotY(true, false)).situation();
        p.choose(far, true);
        assertFalse(p.done(far), "2.5 cm beyond the spot: not yet");
        assertEquals(new Move.Walk(0, true), p.decide(far).move());
        var close = World.at(0, 0, 0).ballRel(k.spotX(true) + 0.008, k.spotY(true, false)).situation();
        assertTrue(p.done(close), "within toleranceFarX (1 cm) of the spot");
        var near = World.at(0, 0, 0).ballRel(k.spotX(true) - 0.025, k.spotY(true, false)).situation();
        assertTrue(p.done(near), "on the near side the band stays 3 cm: no step back for a ball 2.5 cm short");
    }

    @Test
    void prepareForKickStepsBackFromABallAtTheFeet() {
        PrepareForKick p = new PrepareForKick(C);
        var atFeet = World.at(0, 0, 0).ballRel(0.10, -0.055).situation();   // 7 cm short of the 0.17 m spot
        assertFalse(p.done(atFeet), "a ball at the feet is not ready: it would be kicked off the shin");
        assertEquals(new Move.StepBack(), p.decide(atFeet).move());
        // Too close and off to the side: back first (a side step there would push the ball).
        assertEquals(new Move.StepBack(), p.decide(World.at(0, 0, 0).ballRel(0.12, 0.05).situation()).move());
        // Just inside the band's near edge (0.17 - 0.03): no more stepping back.
        var nearEdge = World.at(0, 0, 0).ballRel(0.142, -0.055).situation();
        assertTrue(p.done(nearEdge));
        assertEquals(Move.STAND, p.decide(nearEdge).move());
        // Back in the band but to the side: side step as before.
        assertEquals(new Move.SideStep(true), p.decide(World.at(0, 0, 0).ballRel(0.16, 0.0).situation()).move());
    }

    @Test
    void walkToBallWalksTurnsAndStops() {
        WalkToBall w = new WalkToBall(C);
        Decision far = w.decide(World.at(0, 0, 0).ballRel(3, -0.055).situation());
        assertEquals(new Move.Walk(0, false), far.move(), "aims the right foot at the ball: straight on");
        assertTrue(w.decide(World.at(0, 0, 0).ballRel(0, 2).situation()).move() instanceof Move.Turn t && t.left());
        assertTrue(((Move.Walk) w.decide(World.at(0, 0, 0).ballRel(0.5, -0.055).situation()).move()).slow());
        var close = World.at(0, 0, 0).ballRel(0.2, -0.05).situation();
        assertTrue(w.done(close));
        assertEquals(Move.STAND, w.decide(close).move());
        assertTrue(w.decide(World.at(0, 0, 0).situation()).move() instanceof Move.Turn, "no ball: looks for it");
    }
}

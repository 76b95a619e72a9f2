package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;

import static org.junit.jupiter.api.Assertions.*;

class WalkActionsTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;

    private static void assertWalk(double lean, Move m) {
        assertTrue(m instanceof Move.Walk, m.toString());
        assertEquals(lean, ((Move.Walk) m).lean(), 1e-9);
        assertFalse(((Move.Walk) m).slow());
    }

    @Test
    void walkToDirectionLeansBelowSevenDegreesAndTurnsAbove() {
        assertWalk(5.0 / 7, new WalkToDirection(C, 5).decide(World.at(0, 0, 0).situation()).move());
        assertWalk(-5.0 / 7, new WalkToDirection(C, 5).decide(World.at(0, 0, 10).situation()).move());
        assertWalk(0, new WalkToDirection(C, 0).decide(World.at(0, 0, 0).situation()).move());
        assertWalk(6.9 / 7, new WalkToDirection(C, 6.9).decide(World.at(0, 0, 0).situation()).move());
        assertTrue(new WalkToDirection(C, 7.1).decide(World.at(0, 0, 0).situation()).move() instanceof Move.Turn);
        Move left = new WalkToDirection(C, 20).decide(World.at(0, 0, 0).situation()).move();
        Move right = new WalkToDirection(C, -8).decide(World.at(0, 0, 0).situation()).move();
        assertTrue(left instanceof Move.Turn t && t.left(), left.toString());
        assertTrue(right instanceof Move.Turn t && !t.left(), right.toString());
        assertFalse(new WalkToDirection(C, 0).done(World.at(0, 0, 0).situation()), "runs until replaced");
    }

    @Test
    void walkToDirectionTakesTheShortWayRound() {
        // Heading 170°, direction -170°: 20° to the left, not 340° to the right.
        Move m = new WalkToDirection(C, -170).decide(World.at(0, 0, 170).situation()).move();
        assertTrue(m instanceof Move.Turn t && t.left(), m.toString());
    }

    @Test
    void walkToDirectionLocalizesFirstWithoutASelfPose() {
        Move m = new WalkToDirection(C, 0).decide(World.lost().situation()).move();
        assertTrue(m instanceof Move.Turn t && t.left(), m.toString());
    }

    @Test
    void walkToCoordinateWalksSlowsDownTurnsToThetaAndIsDone() {
        WalkToCoordinate w = new WalkToCoordinate(C, 3, 0, 90);
        assertEquals(new Move.Walk(0, false), w.decide(World.at(0, 0, 0).situation()).move());
        assertEquals(new Move.Walk(0, true), w.decide(World.at(2.5, 0, 0).situation()).move(), "0.5 m away: slow");
        Move turn = w.decide(World.at(2.9, 0, 0).situation()).move();
        assertTrue(turn instanceof Move.Turn t && t.left(), "there: turn to 90°, " + turn);
        assertFalse(w.done(World.at(2.9, 0, 0).situation()));
        var there = World.at(2.9, 0, 85).situation();
        assertEquals(Move.STAND, w.decide(there).move());
        assertTrue(w.done(there));
        // Pushed 0.4 m away: still within twice the tolerance, it stays.
        assertEquals(Move.STAND, w.decide(World.at(3.4, 0, 85).situation()).move());
        // A fresh walk from there goes back (target behind: turn first).
        assertTrue(new WalkToCoordinate(C, 3, 0, 90).decide(World.at(3.4, 0, 0).situation()).move() instanceof Move.Turn);
    }

    @Test
    void walkToCoordinateSteersAwayFromAnObstacleInThePath() {
        // An opponent 1 m ahead, slightly left of the way to (3, 0): the route passes it on the right.
        World w = World.at(0, 0, 0).opponentAt(2, 1, 0.1);
        Move m = new WalkToCoordinate(C, 3, 0, 0).decide(w.situation()).move();
        assertTrue(m instanceof Move.Turn t && !t.left(), m.toString());
        Move free = new WalkToCoordinate(C, 3, 0, 0).decide(World.at(0, 0, 0).opponentAt(2, 1, 1.5).situation()).move();
        assertEquals(new Move.Walk(0, false), free);
    }

    @Test
    void walkToCoordinateRetargetKeepsArrivalForSmallMoves() {
        WalkToCoordinate w = new WalkToCoordinate(C, 3, 0, 0);
        w.decide(World.at(3, 0, 0).situation());
        w.target(3.1, 0, 0);
        assertEquals(Move.STAND, w.decide(World.at(3.35, 0, 0).situation()).move(), "still arrived: 0.25 m < 2 × 0.25");
        w.target(6, 0, 0);
        assertTrue(w.decide(World.at(3.35, 0, 0).situation()).move() instanceof Move.Walk);
        w.target(Double.NaN, 0, 0);
        assertEquals(6, w.target().x(), "a NaN target is ignored");
    }

    @Test
    void dribbleKeepsTheBallInFrontAndAlignsAroundIt() {
        // The thesis's way to a ball away from the feet (Walk To Ball, steps); ours with the approach on is the next test.
        DribbleBallToDirection d = new DribbleBallToDirection(C.withApproach(AgentConfig.Approach.THESIS), 0);
        Move on = d.decide(World.at(0, 0, 0).ballRel(0.2, 0).situation()).move();
        assertEquals(new Move.Walk(0, false), on);
        Move leanToBall = d.decide(World.at(0, 0, 0).ballRel(0.2, 0.05).situation()).move();
        assertEquals(new Move.Walk(0.5, false), leanToBall);
        d.direction(40);   // wanted heading 40° left: go round the ball clockwise, i.e. step right
        assertEquals(new Move.SideStep(false), d.decide(World.at(0, 0, 0).ballRel(0.2, 0).situation()).move());
        assertTrue(d.decide(World.at(0, 0, 0).ballRel(2, 0).situation()).move() instanceof Move.Walk, "ball away: walk to it");
        // Within the 0.28 m stopping distance but off the feet (|y| >= 0.15 m): step to it, never just stand.
        d.direction(0);
        assertEquals(new Move.SideStep(false), d.decide(World.at(0, 0, 0).ballRel(0.12, -0.2).situation()).move());
        assertEquals(new Move.SideStep(true), d.decide(World.at(0, 0, 0).ballRel(0.1, 0.2).situation()).move());
        assertEquals(new Move.StepBack(), d.decide(World.at(0, 0, 0).ballRel(0.02, 0.2).situation()).move(), "beside the heel");
    }

    @Test
    void withTheApproachOnTheDribbleWalksToABallAwayFromItsFeetWithTheOmnidirectionalWalkBehindItAlongItsDirection() {
        DribbleBallToDirection d = new DribbleBallToDirection(C, 0);
        // Ball 2 m ahead, 0.5 m left, dribbled along +x: to 0.22 m behind it, walking forward and left, turning left.
        Move m = d.decide(World.at(0, 0, 0).ballRel(2, 0.5).situation()).move();
        assertTrue(m instanceof Move.Omni o && o.forward() > 0 && o.left() > 0 && o.turn() > 0, m.toString());
        // Ball 0.3 m ahead and 0.3 m to the right, off the feet: walked to sideways, no side step on the spot.
        m = d.decide(World.at(0, 0, 0).ballRel(0.3, -0.3).situation()).move();
        assertTrue(m instanceof Move.Omni o && o.left() < 0, m.toString());
        // Ball behind the robot (the robot is past it along the direction): to the point beside the ball, not through it.
        m = d.decide(World.at(0, 0, 0).ballRel(-0.5, 0).situation()).move();
        assertTrue(m instanceof Move.Omni o && o.forward() < 0 && o.left() > 0, m.toString());
        // At the feet it is the dribble itself.
        assertEquals(new Move.Walk(0, false), d.decide(World.at(0, 0, 0).ballRel(0.2, 0).situation()).move());
    }
}

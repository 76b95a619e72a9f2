package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.localization.fall.FallState;
import phalanx.model.field.Vector2;

import static org.junit.jupiter.api.Assertions.*;

class FieldPlayerBehaviourTest {
    /** The thesis's On Ball (Walk To Ball, then the align orbit); ApproachBallTest has ours. */
    private static final AgentConfig C = AgentConfig.DEFAULT.withApproach(AgentConfig.Approach.THESIS);
    private static final Vector2 HOME = new Vector2(-5, 2);

    @Test
    void theSameOrderKeepsTheSameInstanceSoOnBallKeepsItsState() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.of(5, ActionId.ON_BALL));
        b.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        var first = b.running();
        assertEquals(OnBall.State.ALIGN, ((OnBall) first).state());
        b.order(Action.of(5, ActionId.ON_BALL));      // the next round repeats the order
        b.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        assertSame(first, b.running());
        assertEquals(OnBall.State.ALIGN, ((OnBall) b.running()).state());
        b.order(Action.walkTo(5, 1, 2, 0));
        b.decide(World.at(0, 0, 0).ballRel(2, 0).situation(), false, HOME);
        assertTrue(b.running() instanceof WalkToCoordinate);
        b.order(Action.of(5, ActionId.ON_BALL));
        b.decide(World.at(0, 0, 0).ballRel(2, 0).situation(), false, HOME);
        assertNotSame(first, b.running(), "a new On Ball order after another action starts afresh");
    }

    @Test
    void anOnBallPlayerWithTheBallAtItsFeetKeepsItWhenOrderedElsewhere() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.of(5, ActionId.ON_BALL));
        b.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        var onBall = b.running();
        // Ordered to a position (or to localize) with the ball 0.25 m ahead: it stays on the ball.
        b.order(Action.walkTo(5, 1, 2, 0));
        b.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        assertSame(onBall, b.running());
        b.order(Action.of(5, ActionId.TURN_TO_LOCALIZE));
        b.decide(World.at(0, 0, 90).ballRel(0.3, 0).situation(), false, HOME);
        assertSame(onBall, b.running());
        // Once the ball is beyond keepBallWithin (0.5 m) the order is carried out.
        b.decide(World.at(0, 0, 90).ballRel(0.8, 0).situation(), false, HOME);
        assertTrue(b.running() instanceof TurnToLocalize, b.running().toString());
        // With keepBallWithin 0 the order is carried out at once, as before.
        FieldPlayerBehaviour c = new FieldPlayerBehaviour(C.withFallback(new AgentConfig.Fallback(5.0, 0.5, 0)));
        c.order(Action.of(5, ActionId.ON_BALL));
        c.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        c.order(Action.walkTo(5, 1, 2, 0));
        c.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation(), false, HOME);
        assertTrue(c.running() instanceof WalkToCoordinate, c.running().toString());
    }

    @Test
    void newCoordinatesRetargetTheRunningWalk() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.walkTo(5, 1, 2, 0));
        b.decide(World.at(0, 0, 0).situation(), false, HOME);
        var walk = (WalkToCoordinate) b.running();
        b.order(Action.walkTo(5, 1.2, 2.5, 45));
        b.decide(World.at(0, 0, 0).situation(), false, HOME);
        assertSame(walk, b.running());
        assertEquals(1.2, walk.target().x());
        assertEquals(45, walk.target().thetaDeg());
        b.order(Action.towards(5, ActionId.WALK_TO_DIRECTION, 30));
        b.decide(World.at(0, 0, 0).situation(), false, HOME);
        var dir = (WalkToDirection) b.running();
        b.order(Action.towards(5, ActionId.WALK_TO_DIRECTION, -30));
        b.decide(World.at(0, 0, 0).situation(), false, HOME);
        assertSame(dir, b.running());
        assertEquals(-30, dir.direction());
    }

    @Test
    void everyOrderMapsToItsAction() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        for (ActionId id : ActionId.values()) {
            b.order(switch (id.params()) {
                case NONE -> Action.of(5, id);
                case DIRECTION -> Action.towards(5, id, 10);
                case POSE -> Action.walkTo(5, 1, 1, 0);
            });
            b.decide(World.at(0, 0, 0).ballRel(1, 0).situation(), false, HOME);
            String expected = switch (id) {
                case LOOK_STRAIGHT -> "LookStraight";
                case LOOK_FOR_BALL -> "LookForBall";
                case TURN_TO_LOCALIZE -> "TurnToLocalize";
                case STAND_UP -> "StandUp";
                case TURN_TO_BALL -> "TurnToBall";
                case WALK_TO_BALL -> "WalkToBall";
                case ON_BALL -> "OnBall";
                case WALK_TO_COORDINATE -> "WalkToCoordinate";
                case WALK_TO_DIRECTION -> "WalkToDirection";
                case DRIBBLE_TO_DIRECTION -> "DribbleBallToDirection";
                case FIND_OPPONENT_GOAL -> "FindOpponentGoal";
            };
            assertEquals(expected, b.running().getClass().getSimpleName(), id.toString());
        }
    }

    @Test
    void standsUpFirstWhateverTheOrder() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.of(5, ActionId.ON_BALL));
        assertEquals(new Move.StandUp(true), b.decide(World.at(0, 0, 0).ballRel(1, 0).fall(FallState.FALLEN_FRONT).situation(), false, HOME).move());
        // The stand-up is still on its way (not shown as playing yet): it stays requested.
        assertEquals(new Move.StandUp(true), b.decide(World.at(0, 0, 0).ballRel(1, 0).fall(FallState.FALLING).situation(), false, HOME).move());
        FieldPlayerBehaviour c = new FieldPlayerBehaviour(C);
        c.order(Action.of(5, ActionId.ON_BALL));
        assertEquals(Move.STAND, c.decide(World.at(0, 0, 0).ballRel(1, 0).fall(FallState.FALLING).situation(), false, HOME).move(),
                "only falling: wait, do not walk on");
    }

    @Test
    void quietCoordinatorFallbackGoesOnBallWhenNearestElseHome() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.walkTo(5, 1, 2, 0));
        // The coordinator went quiet; the ball 2 m ahead, a teammate 3 m from it: On Ball.
        b.decide(World.at(0, 0, 0).ballAt(2, 0).teammateAt(7, 5, 0).situation(), true, HOME);
        assertTrue(b.running() instanceof OnBall);
        // A teammate 0.8 m from the ball (we are 2 m away): go home, facing the ball.
        b.decide(World.at(0, 0, 0).ballAt(2, 0).teammateAt(7, 2.8, 0).situation(), true, HOME);
        var w = (WalkToCoordinate) b.running();
        assertEquals(HOME.x(), w.target().x());
        assertEquals(new Vector2(7, -2).angleDeg(), w.target().thetaDeg(), 1e-9);
        // Ball 8 m away: beyond the fallback's 5 m: home too.
        b.decide(World.at(0, 0, 0).ballAt(8, 0).situation(), true, HOME);
        assertTrue(b.running() instanceof WalkToCoordinate);
        // No order ever and no home: turn to a known ball, look for an unknown one.
        FieldPlayerBehaviour alone = new FieldPlayerBehaviour(C);
        alone.decide(World.at(0, 0, 0).ballAt(8, 3).situation(), false, null);
        assertTrue(alone.running() instanceof TurnToBall);
        alone.decide(World.at(0, 0, 0).situation(), false, null);
        assertTrue(alone.running() instanceof LookForBall);
    }

    @Test
    void atHomeWithTheBallUnknownTheFallbackLooksForItAndGoesOnBallOnceSeen() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        // On the way home with the ball unknown: walk there.
        b.decide(World.at(0, 0, 0).situation(), true, HOME);
        assertTrue(b.running() instanceof WalkToCoordinate);
        // Arrived, the ball still unknown: look for it (turn and scan), not stand.
        World home = World.at(HOME.x(), HOME.y(), 0);
        b.decide(home.situation(), true, HOME);
        b.decide(home.situation(), true, HOME);
        assertTrue(b.running() instanceof LookForBall, b.running().toString());
        Move m = b.decide(home.situation(), true, HOME).move();
        assertTrue(m instanceof Move.Turn, "turns to search: " + m);
        // Seen 2 m away: On Ball.
        b.decide(World.at(HOME.x(), HOME.y(), 0).ballRel(2, 0).situation(), true, HOME);
        assertTrue(b.running() instanceof OnBall);
    }

    @Test
    void onBallFallbackHasHysteresis() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.decide(World.at(0, 0, 0).ballAt(2, 0).situation(), true, HOME);
        var onBall = b.running();
        assertTrue(onBall instanceof OnBall);
        // A teammate 1.7 m from the ball (0.3 m closer than us): less than the 0.5 m margin, we keep it.
        b.decide(World.at(0, 0, 0).ballAt(2, 0).teammateAt(7, 3.7, 0).situation(), true, HOME);
        assertSame(onBall, b.running());
        b.decide(World.at(0, 0, 0).ballAt(2, 0).teammateAt(7, 3.2, 0).situation(), true, HOME);
        assertTrue(b.running() instanceof WalkToCoordinate);
    }

    @Test
    void gameOverStandsStill() {
        FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
        b.order(Action.of(5, ActionId.ON_BALL));
        World w = World.at(0, 0, 0).ballRel(2, 0);
        w.mode = PlayMode.GAME_OVER;
        assertEquals(Move.STAND, b.decide(w.situation(), false, HOME).move());
    }

    @Test
    void atFineAnOnBallPlayerTracesItsStateMoveBallAndNearestOpponentTenTimesASecondAndNothingAtInfo() {
        var log = java.util.logging.Logger.getLogger(FieldPlayerBehaviour.class.getName());
        var lines = new java.util.ArrayList<String>();
        var h = new java.util.logging.Handler() {
            @Override public void publish(java.util.logging.LogRecord r) { if (r.getLevel() == java.util.logging.Level.FINE) lines.add(r.getMessage()); }
            @Override public void flush() { }
            @Override public void close() { }
        };
        h.setLevel(java.util.logging.Level.ALL);
        var before = log.getLevel();
        log.addHandler(h);
        try {
            FieldPlayerBehaviour b = new FieldPlayerBehaviour(C);
            b.order(Action.of(5, ActionId.ON_BALL));
            b.decide(World.at(0, 0, 0).time(10.00).ballRel(2, 0).opponentAt(3, 2.5, 0.5).situation(), false, HOME);
            assertTrue(lines.isEmpty(), "at INFO (the default) nothing is traced: " + lines);
            log.setLevel(java.util.logging.Level.FINE);
            b.decide(World.at(0, 0, 0).time(10.02).ballRel(2, 0).opponentAt(3, 2.5, 0.5).situation(), false, HOME);
            b.decide(World.at(0, 0, 0).time(10.04).ballRel(2, 0).opponentAt(3, 2.5, 0.5).situation(), false, HOME);
            assertEquals(1, lines.size(), "one line a tenth of a second: " + lines);
            b.decide(World.at(0, 0, 0).time(10.12).ballRel(2, 0).opponentAt(3, 2.5, 0.5).situation(), false, HOME);
            assertEquals(2, lines.size(), lines.toString());
            String l = lines.get(1);
            assertTrue(l.startsWith("trace t=10.1 WALK_TO_BALL move=Walk["), l);
            assertTrue(l.contains("ball=(2.00,0.00)") && l.contains("opp=(2.50,0.50)") && l.contains("self=(0.00,0.00,0)"), l);
            b.order(Action.walkTo(5, 1, 2, 0));
            b.decide(World.at(0, 0, 0).time(10.22).ballRel(2, 0).situation(), false, HOME);
            assertEquals(2, lines.size(), "only On Ball is traced: " + lines);
        } finally {
            log.removeHandler(h);
            log.setLevel(before);
        }
    }
}

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;

import static org.junit.jupiter.api.Assertions.*;

class HeadActionsTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;   // pan ±90° over 2 s, scan down to -35°

    @Test
    void lookStraightZeroesBothJoints() {
        var d = new LookStraight().decide(World.at(0, 0, 0).situation());
        assertEquals(HeadTarget.STRAIGHT, d.head());
        assertEquals(Move.STAND, d.move());
    }

    @Test
    void panHeadSweepsBetweenTheAmplitudesAtZeroTilt() {
        PanHead pan = new PanHead(C);
        assertEquals(-90, pan.head(World.at(0, 0, 0).time(10.0).situation()).yawDeg(), 1e-9);   // period start
        assertEquals(0, pan.head(World.at(0, 0, 0).time(10.5).situation()).yawDeg(), 1e-9);   // quarter: centre
        assertEquals(90, pan.head(World.at(0, 0, 0).time(11.0).situation()).yawDeg(), 1e-9);  // half: left end
        assertEquals(45, pan.head(World.at(0, 0, 0).time(11.25).situation()).yawDeg(), 1e-9); // on the way back
        assertEquals(0, pan.head(World.at(0, 0, 0).time(11.6).situation()).pitchDeg());
    }

    @Test
    void scanLooksFarGoingLeftAndNearComingBack() {
        Scan scan = new Scan(C);
        HeadTarget out = scan.head(World.at(0, 0, 0).time(10.5).situation());
        HeadTarget back = scan.head(World.at(0, 0, 0).time(11.5).situation());
        assertEquals(0, out.pitchDeg());
        assertEquals(-35, back.pitchDeg());
        assertEquals(0, out.yawDeg(), 1e-9);
        assertEquals(0, back.yawDeg(), 1e-9);
    }

    @Test
    void trackObjectCentresTheBallFromTheCameraHeight() {
        // No joint readings: standing camera height of a type-0 robot, 0.385 + 0.155 = 0.54 m.
        HeadTarget h = TrackObject.ball(C).head(World.at(0, 0, 0).ballRel(1, 1).situation());
        assertEquals(45, h.yawDeg(), 1e-9);
        assertEquals(-Math.toDegrees(Math.atan2(0.54 - 0.042, Math.sqrt(2))), h.pitchDeg(), 1e-6);  // -19.4°
        HeadTarget right = TrackObject.ball(C).head(World.at(0, 0, 0).ballRel(2, -2).situation());
        assertEquals(-45, right.yawDeg(), 1e-9);
        assertTrue(right.pitchDeg() > h.pitchDeg(), "a farther ball needs less pitch down");
    }

    @Test
    void aTallerRobotTypeLooksDownMore() {
        // Type 3: legs 0.1479 + 0.1279 m instead of 0.12 + 0.10: camera at 0.5958 m.
        HeadTarget t3 = TrackObject.ball(AgentConfig.forRobotType(3)).head(World.at(0, 0, 0).ballRel(1, 0).situation());
        assertEquals(-Math.toDegrees(Math.atan2(0.115 + 0.147868424 + 0.127868424 + 0.05 + 0.155 - 0.042, 1)), t3.pitchDeg(), 1e-6);
        var e = assertThrows(IllegalArgumentException.class, () -> AgentConfig.forRobotType(7));
        assertEquals("robot type must be 0-4, got 7", e.getMessage());
    }

    @Test
    void trackObjectPansWithoutTheObject() {
        TrackObject t = TrackObject.ball(C);
        World w = World.at(0, 0, 0).time(11.0);    // ball never seen
        assertEquals(90, t.head(w.situation()).yawDeg(), 1e-9);
    }

    @Test
    void trackObjectFollowsAFixedPointOfTheField() {
        // Facing +y at the origin: the point (0, -3) is straight behind, (3, 0) to the right.
        TrackObject t = TrackObject.point(C, new phalanx.model.field.Vector2(3, 0), 0);
        assertEquals(-90, t.head(World.at(0, 0, 90).situation()).yawDeg(), 1e-9);
    }

    @Test
    void trackMovingObjectGivesTheBodyFrameVelocityAndLeadsTheBall() {
        TrackMovingObject t = new TrackMovingObject(C);
        // Facing +y; the ball rolls toward -y in the own frame: toward us, i.e. -x in the body frame.
        World w = World.at(0, 0, 90).ballRel(2, 0).ballVelocity(0, -1);
        var v = t.relativeVelocity(w.situation());
        assertEquals(-1, v.x(), 1e-9);
        assertEquals(0, v.y(), 1e-9);
        World side = World.at(0, 0, 0).ballRel(2, 0).ballVelocity(0, 2);   // rolling to our left
        assertTrue(t.head(side.situation()).yawDeg() > 0, "leads the ball to the left");
    }
}

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.model.field.Vector2;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class AvoidObstaclesTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;                    // clearance 0.45 m
    private static final AgentConfig.Obstacles HALF = new AgentConfig.Obstacles(2.0, 0.5, 0.5);

    @Test
    void oneObstacleGivesTwoTangentEscapes() {
        // 1 m ahead, clearance 0.5 m: asin(0.5) = 30° each side; the way points are the tangent points.
        var set = AvoidObstacles.escapeAngleSet(List.of(new Vector2(1, 0)), 0.5);
        assertEquals(2, set.size());
        assertEquals(30, set.get(0).angleDeg(), 1e-9);
        assertEquals(-30, set.get(1).angleDeg(), 1e-9);
        assertEquals(Math.cos(Math.toRadians(30)), set.get(0).waypoint().norm(), 1e-9);
        assertEquals(0.5, set.get(0).waypoint().distanceTo(new Vector2(1, 0)), 1e-9, "passes at the clearance");
    }

    @Test
    void algorithm2DropsEscapesInsideAnotherObstaclesForbiddenInterval() {
        // Two obstacles side by side (Figure 4.12): bearings ±16.70°, half-angles asin(0.5/1.044) = 28.61°.
        // The inner escapes (-11.9° and +11.9°) fall inside the other one's interval: only the outer two remain.
        var set = AvoidObstacles.escapeAngleSet(List.of(new Vector2(1, 0.3), new Vector2(1, -0.3)), 0.5);
        double b = Math.toDegrees(Math.atan2(0.3, 1)), h = Math.toDegrees(Math.asin(0.5 / Math.hypot(1, 0.3)));
        assertEquals(2, set.size());
        assertEquals(b + h, set.get(0).angleDeg(), 1e-9);
        assertEquals(-(b + h), set.get(1).angleDeg(), 1e-9);
    }

    @Test
    void aBlockedWayBendsToTheCheaperSide() {
        // Obstacle slightly left of the way to (3, 0): the right escape (-24.1°, detour 0.105 m) beats
        // the left one (+35.5°, detour 0.218 m).
        Vector2 way = AvoidObstacles.route(List.of(new Vector2(1, 0.1)), new Vector2(3, 0), HALF);
        assertTrue(way.y() < 0, "passes on the right: " + way);
        assertEquals(-24.12, way.angleDeg(), 0.01);
        Vector2 mirrored = AvoidObstacles.route(List.of(new Vector2(1, -0.1)), new Vector2(3, 0), HALF);
        assertEquals(24.12, mirrored.angleDeg(), 0.01);
    }

    @Test
    void aClearWayIsTheTargetItself() {
        Vector2 target = new Vector2(3, 0);
        assertSame(target, AvoidObstacles.route(List.of(new Vector2(1, 1)), target, HALF), "beside the way");
        assertSame(target, AvoidObstacles.route(List.of(new Vector2(-1, 0)), target, HALF), "behind");
        Vector2 near = new Vector2(1, 0);
        assertSame(near, AvoidObstacles.route(List.of(new Vector2(2, 0)), near, HALF), "beyond the target");
        assertSame(target, AvoidObstacles.route(List.of(), target, HALF));
    }

    @Test
    void theSameObstaclesGiveTheSameWayPointEveryCycle() {
        List<Vector2> obstacles = List.of(new Vector2(1, 0.2), new Vector2(1.5, -0.4));
        Vector2 a = AvoidObstacles.route(obstacles, new Vector2(4, 0), HALF);
        Vector2 b = AvoidObstacles.route(obstacles, new Vector2(4, 0), HALF);
        assertEquals(a, b);
    }

    @Test
    void obstaclesArePlayersSeenLatelyWithinTwoMetresAndNearGoalPosts() {
        World w = World.at(0, 0, 0).opponentAt(3, 1, 0.2).teammateAt(4, 3, 0);
        w.opponents.add(new phalanx.localization.belief.PlayerBelief("Them", 9, w.now - 5, new Vector2(0.5, 0),
                new Vector2(0.5, 0), new Vector2[phalanx.comm.perception.BodyPart.COUNT], null));
        var list = new AvoidObstacles(C).obstacles(w.situation());
        assertEquals(List.of(new Vector2(1, 0.2)), list, "the 3 m teammate and the 5 s old opponent do not count");
        var posts = new AvoidObstacles(C).obstacles(World.at(13.5, 0, 0).situation());
        assertEquals(2, posts.size(), "the opponent goal's posts 1.5 m ahead");
    }
}

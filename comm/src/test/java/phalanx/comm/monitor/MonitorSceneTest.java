package phalanx.comm.monitor;

import org.junit.jupiter.api.Test;
import phalanx.comm.recording.Recordings;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Reads the monitor stream recorded from the real server (M1: full graphs, then partial updates,
 * recordings README) and checks the torso and ball poses against the trainer commands of that run.
 */
class MonitorSceneTest {
    private static List<String> m1() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        return Files.readAllLines(Recordings.dir().get().resolve("M1_monitor.txt"), StandardCharsets.ISO_8859_1);
    }

    @Test
    void followsTheRecordedRunThroughFullAndPartialUpdates() throws Exception {
        List<String> lines = m1();
        MonitorScene s = new MonitorScene();
        s.apply(lines.get(0));
        assertNull(s.torso(1, "Left"), "line 1 is the scene before the robot exists");
        assertArrayEquals(new double[] {0, 0, 0.04}, s.ball(), 0.003);
        s.apply(lines.get(1));
        s.apply(lines.get(2));
        MonitorScene.Pose spawn = s.torso(1, "Left");
        assertEquals(-14.2, spawn.x(), 1e-6);
        assertEquals(9.2, spawn.y(), 1e-6);
        assertEquals(0.0, spawn.yawDeg(), 0.01);
        assertNull(s.torso(1, "Right"));
        assertNull(s.torso(2, "Left"));
        // Body parts: the torso's own centre is one of them, every other within a robot's size of it,
        // the highest (the head) above it and the lowest (the feet) near the ground's level of the hanging robot.
        List<double[]> parts = s.parts(1, "Left");
        assertTrue(parts.size() >= 14, "parts: " + parts.size());
        assertTrue(parts.stream().anyMatch(q -> Math.hypot(q[0] - spawn.x(), q[1] - spawn.y()) < 1e-6 && Math.abs(q[2] - spawn.z()) < 1e-6));
        double top = parts.stream().mapToDouble(q -> q[2]).max().orElseThrow();
        double bottom = parts.stream().mapToDouble(q -> q[2]).min().orElseThrow();
        assertTrue(top > spawn.z() + 0.05 && top < spawn.z() + 0.3, "head at " + top);
        assertTrue(bottom < spawn.z() - 0.25 && bottom > spawn.z() - 0.45, "feet at " + bottom);
        assertTrue(parts.stream().allMatch(q -> Math.hypot(q[0] - spawn.x(), q[1] - spawn.y()) < 0.3));
        assertNull(s.parts(2, "Left"));

        boolean sawBeam = false, sawHang = false, sawBall = false;
        for (String line : lines.subList(3, lines.size())) {
            s.apply(line); // partial (RDS) updates from here on
            MonitorScene.Pose p = s.torso(1, "Left");
            // (beam -3 1 45): noise up to 5 cm and 10 deg (DESIGN.md).
            if (Math.abs(p.x() + 3) < 0.05 && Math.abs(p.y() - 1) < 0.05 && Math.abs(p.yawDeg() - 45) < 10) sawBeam = true;
            // (agent (unum 1) (team Left) (pos -3 0 0.35)): hangs at z = 0.35.
            if (Math.abs(p.x() + 3) < 1e-3 && Math.abs(p.y()) < 1e-3 && Math.abs(p.z() - 0.35) < 1e-3) sawHang = true;
            double[] b = s.ball();
            if (Math.abs(b[0] - 2) < 1e-3 && Math.abs(b[1] - 1) < 1e-3) sawBall = true; // (ball (pos 2 1 0.042)) in PlayOn
        }
        assertTrue(sawBeam && sawHang && sawBall, "beam " + sawBeam + ", hang " + sawHang + ", ball " + sawBall);
        // Last command: (agent (unum 1) (team Left) (move -2 2 0.4 0)), angle 0 = facing +y = 90 deg.
        MonitorScene.Pose end = s.torso(1, "Left");
        assertEquals(-2.0, end.x(), 1e-3);
        assertEquals(2.0, end.y(), 1e-3);
        assertEquals(0.4, end.z(), 1e-3);
        assertEquals(90.0, end.yawDeg(), 0.1);
        assertEquals(1.0, end.upZ(), 1e-3);
        assertEquals(3, s.playMode(), "PlayOn is play mode 3 in the header's list");
        assertEquals(5.36, s.time(), 1e-9);
        assertEquals(lines.size(), s.messages());
    }

    @Test
    void badMonitorTextIsReportedClearly() {
        MonitorScene s = new MonitorScene();
        IllegalArgumentException trunc = assertThrows(IllegalArgumentException.class, () -> s.apply("((time 1))(RSG 0 1)((nd TRF (SLT 1 0"));
        assertTrue(trunc.getMessage().contains("unbalanced"), trunc.getMessage());
        IllegalArgumentException slt = assertThrows(IllegalArgumentException.class, () -> s.apply("((time 1))(RSG 0 1)((nd TRF (SLT 1 0 0)))"));
        assertTrue(slt.getMessage().contains("SLT needs 16 numbers, got 3"), slt.getMessage());
        IllegalArgumentException time = assertThrows(IllegalArgumentException.class, () -> s.apply("((time soon))"));
        assertTrue(time.getMessage().contains("'soon'"), time.getMessage());
        assertThrows(IllegalArgumentException.class, () -> s.apply("garbage"));
        s.apply("((time 2))(RDS 0 1)((nd))"); // a partial update before any full scene is ignored
        assertFalse(s.hasScene());
        assertEquals(2.0, s.time());
    }
}

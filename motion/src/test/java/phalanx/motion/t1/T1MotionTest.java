package phalanx.motion.t1;

import org.junit.jupiter.api.Test;
import phalanx.model.robot.T1Joints;
import phalanx.motion.MotionFileException;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** T1 keyframe motions: the Webots text format with T1 joint names (T1MotionLoader) and their player. */
class T1MotionTest {
    private static final String TWO = """
            #WEBOTS_MOTION,V1.0
            # a knee and a hip, radians
            Left_Knee_Pitch,Right_Hip_Pitch
            00:00:200,bend,1.0,-0.5
            00:00:600,back,*,0
            """;

    private static T1Motion parse(String text) throws MotionFileException {
        return T1MotionLoader.parse("two", "two.motion", text);
    }

    @Test
    void readsT1JointNamesAsActuatorsInDegrees() throws Exception {
        T1Motion m = parse(TWO);
        assertEquals(List.of("lle4", "rle1"), m.actuators());
        assertEquals(List.of("bend", "back"), m.poseNames());
        assertArrayEquals(new int[]{200, 600}, m.timesMs());
        assertEquals(Math.toDegrees(1.0), m.posesDeg()[0][0], 1e-9);
        assertEquals(Math.toDegrees(1.0), m.posesDeg()[1][0], 1e-9, "'*' keeps the previous pose's value");
        assertEquals(0.6, m.seconds(), 1e-12);
    }

    @Test
    void refusesNaoNamesAndValuesOutsideTheT1Range() {
        MotionFileException nao = assertThrows(MotionFileException.class, () -> parse(TWO.replace("Left_Knee_Pitch", "LKneePitch")));
        assertEquals(3, nao.line());
        assertTrue(nao.getMessage().contains("unknown joint 'LKneePitch'") && nao.getMessage().contains("Left_Knee_Pitch"), nao.getMessage());
        // the knee bends 0..2.34 rad only (t1-joints.tsv)
        MotionFileException range = assertThrows(MotionFileException.class, () -> parse(TWO.replace("bend,1.0", "bend,-0.2")));
        assertEquals(4, range.line());
        assertEquals("Left_Knee_Pitch", range.field());
        assertTrue(range.getMessage().contains("outside its range [0.0, 134.07]"), range.getMessage());
    }

    @Test
    void playsFromTheMeasuredAnglesThroughEachPoseWithItsVelocity() throws Exception {
        T1Motion m = parse(TWO);
        T1MotionPlayer p = new T1MotionPlayer(0.02, T1MotionPlayer.Gains.DEFAULT);
        Map<String, Double> measured = new HashMap<>(Map.of("lle4", 20.0, "rle1", 0.0, "lae1", -30.0));
        p.start(m, a -> measured.getOrDefault(a, 0.0));
        double knee = Math.toDegrees(1.0), hip = Math.toDegrees(-0.5);
        Map<String, JointCommand> c = null;
        for (int i = 1; i <= 5; i++) c = byActuator(p.next());   // t = 0.1 s: half way to the first pose
        assertEquals(20 + (knee - 20) / 2, c.get("lle4").qDeg(), 1e-9);
        assertEquals((knee - 20) / 0.2, c.get("lle4").dqDeg(), 1e-6, "the velocity of the interpolation, deg/s");
        assertEquals(hip / 2, c.get("rle1").qDeg(), 1e-9);
        assertEquals(-30, c.get("lae1").qDeg(), 1e-9, "a joint the file does not name holds its start angle");
        assertEquals(0, c.get("lae1").dqDeg(), 1e-9);
        assertEquals(T1Joints.ALL.size(), c.size(), "a command for every actuator");
        assertEquals(200, c.get("lle4").kp());
        assertEquals(100, c.get("lae1").kp());
        for (int i = 6; i <= 20; i++) c = byActuator(p.next());  // t = 0.4 s: half way from bend to back
        assertEquals(knee, c.get("lle4").qDeg(), 1e-9);
        assertEquals(hip / 2, c.get("rle1").qDeg(), 1e-9);
        assertEquals("back", p.poseName());
        assertTrue(p.active());
        for (int i = 21; i <= 30; i++) c = byActuator(p.next());  // t = 0.6 s: the last pose, and done
        assertFalse(p.active());
        assertEquals(0, c.get("rle1").qDeg(), 1e-9);
        assertEquals(0, c.get("rle1").dqDeg(), 1e-9, "still at the end");
        assertEquals("done", p.poseName());
    }

    private static Map<String, JointCommand> byActuator(List<JointCommand> cmds) {
        Map<String, JointCommand> m = new HashMap<>();
        for (JointCommand c : cmds) assertNull(m.put(c.actuator(), c), "one command per actuator: " + c.actuator());
        return m;
    }
}

package phalanx.motion.webots;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.comm.perception.Joint;
import phalanx.motion.MotionFileException;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class TextMotionLoaderTest {
    @TempDir Path dir;

    private static final String TURN = """
            #WEBOTS_MOTION,V1.0
            # a comment
            LHipYawPitch,LHipRoll,LHipPitch,LKneePitch,HeadPitch
            00:00:000,Pose1,0,-0.1,-0.5,1.0,0.2
            00:00:040,Pose2,-0.2,*,-0.4,0.8,0
            """;

    private static TextMotion parse(String text) throws Exception {
        return TextMotionLoader.parse("turn", "turn.motion", new StringReader(text));
    }

    private static MotionFileException fails(String text) {
        return assertThrows(MotionFileException.class, () -> parse(text));
    }

    @Test
    void mapsWebotsNamesToSimulatorJointsDegreesAndSigns() throws Exception {
        TextMotion m = parse(TURN);
        assertEquals(List.of(Joint.LLJ1, Joint.LLJ2, Joint.LLJ3, Joint.LLJ4, Joint.HJ2), m.joints());
        assertEquals(List.of("Pose1", "Pose2"), m.poseNames());
        assertArrayEquals(new int[] {0, 40}, m.timesMs());
        // Pitch joints change sign (Aldebaran y-left axis vs the simulator's x-right axis).
        assertEquals(0.0, m.targetDeg(0, 0), 1e-9);
        assertEquals(Math.toDegrees(-0.1), m.targetDeg(0, 1), 1e-9);   // roll keeps its sign
        assertEquals(Math.toDegrees(0.5), m.targetDeg(0, 2), 1e-9);    // hip pitch: -0.5 -> +28.6 deg
        assertEquals(Math.toDegrees(-1.0), m.targetDeg(0, 3), 1e-9);   // knee: 1.0 -> -57.3 deg
        assertEquals(Math.toDegrees(-0.2), m.targetDeg(0, 4), 1e-9);   // head pitch
        assertEquals(Math.toDegrees(-0.2), m.targetDeg(1, 0), 1e-9);   // hip yaw-pitch keeps its sign
        assertEquals(Math.toDegrees(-0.1), m.targetDeg(1, 1), 1e-9);   // '*' repeats the previous pose
    }

    @Test
    void headerMayFollowTheMagicOnOneLine() throws Exception {
        TextMotion m = parse("#WEBOTS_MOTION,V1.0,HeadYaw,RKneePitch\n00:00:000,P1,0.1,0.5\n00:01:500,P2,0,0\n");
        assertEquals(List.of(Joint.HJ1, Joint.RLJ4), m.joints());
        assertArrayEquals(new int[] {0, 1500}, m.timesMs());
    }

    @Test
    void loadsFromAFileNamedAfterIt() throws IOException, MotionFileException {
        Path f = dir.resolve("turn_left.motion");
        Files.writeString(f, TURN);
        assertEquals("turn_left", TextMotionLoader.load(f).name());
    }

    @Test
    void errorsNameLinePoseAndField() {
        MotionFileException magic = fails("LHipRoll\n00:00:000,P,0\n");
        assertEquals(1, magic.line());
        assertEquals("header", magic.field());
        MotionFileException joint = fails(TURN.replace("LKneePitch", "LKnee"));
        assertEquals(3, joint.line());
        assertEquals("header/LKnee", joint.field());
        assertTrue(joint.getMessage().contains("unknown joint 'LKnee'"), joint.getMessage());
        MotionFileException twice = fails(TURN.replace("LKneePitch", "LHipRoll"));
        assertTrue(twice.getMessage().contains("listed twice"), twice.getMessage());
        MotionFileException count = fails(TURN.replace("0.8,0\n", "0.8\n"));
        assertEquals(5, count.line());
        assertEquals("pose 'Pose2'", count.part());
        assertTrue(count.getMessage().contains("has 4 joint values, the header lists 5"), count.getMessage());
        MotionFileException value = fails(TURN.replace("-0.4", "abc"));
        assertEquals("llj3", value.field());
        assertEquals("pose 'Pose2'", value.part());
        MotionFileException range = fails(TURN.replace("0,-0.1,-0.5", "0,-0.1,0.7")); // hip pitch -40 deg < -25
        assertEquals("llj3", range.field());
        assertTrue(range.getMessage().contains("outside its range [-25.0, 100.0]"), range.getMessage());
        MotionFileException time = fails(TURN.replace("00:00:040", "00:00:000"));
        assertEquals("time", time.field());
        MotionFileException badTime = fails(TURN.replace("00:00:040", "0.04"));
        assertTrue(badTime.getMessage().contains("is not mm:ss:mmm"), badTime.getMessage());
        MotionFileException star = fails(TURN.replace("0,-0.1,-0.5", "*,-0.1,-0.5"));
        assertEquals("llj1", star.field());
        MotionFileException noPoses = fails("#WEBOTS_MOTION,V1.0\nHeadYaw\n");
        assertEquals("poses", noPoses.field());
        MotionFileException noHeader = fails("#WEBOTS_MOTION,V1.0\n# only comments\n");
        assertEquals("header", noHeader.field());
        MotionFileException empty = fails("");
        assertEquals("header", empty.field());
    }
}

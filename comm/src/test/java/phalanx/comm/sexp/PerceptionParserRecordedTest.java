package phalanx.comm.sexp;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.FootForce;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.SeenPlayer;
import phalanx.comm.perception.Side;
import phalanx.comm.recording.Recordings;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Decodes real server messages and checks values copied by hand from named lines of
 * ../shared/recordings (needs that folder; skipped with a message when it is missing).
 */
class PerceptionParserRecordedTest {
    private final PerceptionParser parser = new PerceptionParser();

    @BeforeAll
    static void needRecordings() {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
    }

    private Perception line(String recording, int lineNumber) throws Exception {
        List<String> lines = Recordings.perceptorMessages(Recordings.named(recording));
        return parser.parse(lines.get(lineNumber - 1));
    }

    @Test
    void everyMessageOfEveryRecordingParses() throws IOException {
        List<Path> all = Recordings.all();
        assertTrue(all.size() >= 9, "expected the shared recordings, found " + all);
        int messages = 0, visions = 0;
        for (Path rec : all) {
            List<String> lines = Recordings.perceptorMessages(rec);
            for (int i = 0; i < lines.size(); i++) {
                try {
                    Perception p = parser.parse(lines.get(i));
                    assertFalse(Double.isNaN(p.time()), rec + " line " + (i + 1) + " has no time");
                    assertNotNull(p.gameState(), rec + " line " + (i + 1) + " has no GS");
                    assertTrue(p.unknown().isEmpty(), rec + " line " + (i + 1) + " has unknown " + p.unknown());
                    if (p.hasVision()) visions++;
                } catch (MalformedMessageException e) {
                    fail(rec + " line " + (i + 1) + ": " + e.getMessage());
                }
                messages++;
            }
        }
        assertTrue(messages > 7000, "only " + messages + " messages");
        assertTrue(visions > messages / 4, "vision every third message, got " + visions + " of " + messages);
    }

    @Test
    void s1Line1TimeGameStateFlagsBallAndLines() throws Exception {
        // (time (now 0.52))(GS (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff)) ... (See (F1L (pol 18.70 53.49 -5.25))
        // (F1R (pol 18.68 -53.74 -5.04)) (B (pol 1.89 0.33 -58.15)) (L ...) x9)
        Perception p = line("S1", 1);
        assertEquals(0.52, p.time(), 1e-12);
        assertEquals(PlayMode.BEFORE_KICK_OFF, p.gameState().playMode());
        assertEquals(0, p.gameState().scoreLeft());
        assertEquals(0, p.gameState().unum());
        assertNull(p.gameState().side());
        assertEquals(18.70, p.vision().landmark(Landmark.F1L).distance(), 1e-12);
        assertEquals(53.49, p.vision().landmark(Landmark.F1L).horizontalDeg(), 1e-12);
        assertEquals(-5.25, p.vision().landmark(Landmark.F1L).verticalDeg(), 1e-12);
        assertEquals(-53.74, p.vision().landmark(Landmark.F1R).horizontalDeg(), 1e-12);
        assertNull(p.vision().landmark(Landmark.G1L));
        assertEquals(2, p.vision().landmarkCount());
        assertEquals(1.89, p.vision().ball().distance(), 1e-12);
        assertEquals(-58.15, p.vision().ball().verticalDeg(), 1e-12);
        assertEquals(9, p.vision().lines().size());
        assertEquals(11.14, p.vision().lines().get(0).end().distance(), 1e-12);
        assertEquals(0.0, p.joints().degrees(Joint.HJ1), 0);
        assertFalse(p.joints().has(Joint.LLJ7), "type 0 has no toes");
    }

    @Test
    void s1Line3CarriesUnumAndSideOnce() throws Exception {
        // (GS (unum 1) (team left) (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))(GYR ...)(ACC (n torso) (a -0.00 -0.00 29.42))
        Perception p = line("S1", 3);
        assertEquals(1, p.gameState().unum());
        assertEquals(Side.LEFT, p.gameState().side());
        assertEquals(29.42, p.acc().z(), 1e-12);
        assertNull(line("S1", 4).gameState().side());
    }

    @Test
    void s6Line3IsRightSide() throws Exception {
        assertEquals(Side.RIGHT, line("S6", 3).gameState().side());
    }

    @Test
    void s2Line22IsPlayOnWithGameTime() throws Exception {
        // (GS (sl 0) (sr 0) (t 0.02) (pm PlayOn))
        Perception p = line("S2", 22);
        assertEquals(PlayMode.PLAY_ON, p.gameState().playMode());
        assertEquals(0.02, p.gameState().gameTime(), 1e-12);
    }

    @Test
    void s3Line120GyroAndAccelerometerWhileFalling() throws Exception {
        // (GYR (n torso) (rt -0.24 0.00 0.00))(ACC (n torso) (a -0.00 9.78 0.14))
        Perception p = line("S3", 120);
        assertEquals(-0.24, p.gyro().x(), 1e-12);
        assertEquals(9.78, p.acc().y(), 1e-12);
        assertEquals(0.14, p.acc().z(), 1e-12);
    }

    @Test
    void s4Agent1HearsItselfAndTeammate() throws Exception {
        // line 102: (hear Probe 0.00 self hello1); line 159: (hear Probe 0.00 -47.72 fromTwo)
        Hear self = line("S4_agent1", 102).hears().get(0);
        assertEquals("Probe", self.team());
        assertTrue(self.self());
        assertEquals("hello1", self.message());
        Hear other = line("S4_agent1", 159).hears().get(0);
        assertFalse(other.self());
        assertEquals(-47.72, other.directionDeg(), 1e-12);
        assertEquals("fromTwo", other.message());
    }

    @Test
    void s5Agent7ToeSensorsAndOwnArms() throws Exception {
        // line 7: (FRP (n lf1) (c 0.00 -0.00 -0.01) (f -0.00 -0.14 32.22))(HJ (n llj7) (ax 0.00));
        // (P (team ProbeTeam) (id 7) (rlowerarm (pol 0.19 -34.95 -22.66)) ...)
        Perception p = line("S5_agent7", 7);
        FootForce toe = p.footForces().stream().filter(f -> f.foot() == FootForce.Foot.LEFT_TOE).findFirst().orElseThrow();
        assertEquals(32.22, toe.force().z(), 1e-12);
        assertEquals(-0.01, toe.contact().z(), 1e-12);
        assertTrue(p.joints().has(Joint.LLJ7));
        SeenPlayer me = p.vision().players().get(0);
        assertEquals("ProbeTeam", me.team());
        assertEquals(7, me.id());
        assertEquals(-34.95, me.part(BodyPart.RIGHT_LOWER_ARM).horizontalDeg(), 1e-12);
        assertNull(me.part(BodyPart.HEAD));
    }

    @Test
    void s6Line349SeesTheDummyWithEveryPart() throws Exception {
        // (P (team Dummy) (id 1) (head (pol 20.40 58.29 0.16)) (rlowerarm (pol 20.23 59.02 -0.11))
        //  (llowerarm (pol 20.18 58.40 -0.26)) (rfoot (pol 20.35 58.95 -1.56)) (lfoot (pol 20.31 58.16 -1.43)))
        SeenPlayer dummy = line("S6", 349).vision().players().stream()
                .filter(s -> s.team().equals("Dummy")).findFirst().orElseThrow();
        assertEquals(1, dummy.id());
        assertEquals(20.40, dummy.part(BodyPart.HEAD).distance(), 1e-12);
        assertEquals(-1.43, dummy.part(BodyPart.LEFT_FOOT).verticalDeg(), 1e-12);
        assertEquals(58.95, dummy.part(BodyPart.RIGHT_FOOT).horizontalDeg(), 1e-12);
    }
}

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.model.field.Vector2;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** MjWorld over the real rcssservermj recording (comm/src/test/resources/rcssservermj, README there). */
class MjWorldTest {
    private static final Path RECORDING = Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt");

    private static List<MjPerception> recording() throws Exception {
        MjPerceptionParser parser = new MjPerceptionParser();
        List<MjPerception> out = new java.util.ArrayList<>();
        for (String line : Files.readAllLines(RECORDING)) out.add(parser.parse(line));
        return out;
    }

    @Test
    void leftTeamSeesItsBeamedPoseAndTheBallOnTheCentreSpot() throws Exception {
        MjWorld w = new MjWorld("Phalanx");
        List<MjPerception> rec = recording();
        w.update(rec.get(0));
        assertEquals(1, w.side(), "the recording's team is tl");
        assertEquals(-3, w.self().x(), 1e-3);
        assertEquals(21, w.self().y(), 1e-3);
        assertEquals(-90, w.self().thetaDeg(), 0.1, "placed at the side line facing -y");
        assertTrue(w.beamAllowed(), "BeforeKickOff");
        int ballSightings = 0;
        for (int i = 1; i < 30; i++) {
            Vector2 before = w.ball();
            w.update(rec.get(i));
            if (w.ball() != before) {
                ballSightings++;
                assertEquals(0, w.ball().distanceTo(Vector2.ZERO), 0.1, "ball at " + w.ball() + " in message " + i);
                assertEquals(0, w.ballAge(), 1e-9);
            }
            if (i == 5) {
                assertEquals(-3, w.self().x(), 0.01, "beamed to (-3, 0), seen in message 5");
                assertEquals(0, w.self().y(), 0.01);
            }
        }
        assertTrue(ballSightings >= 5, ballSightings + " ball sightings");
    }

    @Test
    void theRightTeamSeesTheSameWorldTurnedBy180Degrees() throws Exception {
        List<MjPerception> rec = recording();
        MjWorld w = new MjWorld("Other");
        for (MjPerception p : rec.subList(0, 10)) {
            w.update(new MjPerception(p.time(), p.gameTime(), p.playMode(), "Phalanx", "Other", 0, 0, p.quat(), p.pos(),
                    p.gyro(), p.acc(), p.joints(), p.touch(), p.seen(), p.heard(), p.heardSkipped()));
        }
        assertEquals(-1, w.side());
        assertEquals(3, w.self().x(), 0.01);
        assertEquals(0, w.self().y(), 0.01);
        assertEquals(180, Math.abs(w.self().thetaDeg()), 0.1);
        assertTrue(w.ours("KickOff_Right") && !w.ours("KickOff_Left"));
    }

    @Test
    void theLimpRobotFallsAndIsNoLongerUpright() throws Exception {
        MjWorld w = new MjWorld("Phalanx");
        List<MjPerception> rec = recording();
        w.update(rec.get(5));
        assertTrue(w.upright());
        for (MjPerception p : rec) w.update(p);
        assertFalse(w.upright(), "lying at the end of the recording");
        assertEquals(300 + 1, w.updates());
    }
}

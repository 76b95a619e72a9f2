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

    @Test
    void aSetPieceMovesTheBallWhereTheRefereeDropsIt() {
        // the left team: own frame = world; the ball last seen 3 m ahead of a player at (-22, 4) facing +x: (-19, 4)
        MjWorld w = new MjWorld("Phalanx");
        w.update(MjBehaviourTest.at(1, "PlayOn", -22, 4, 0, 3));
        w.update(MjBehaviourTest.at(1.02, "corner_kick_right", -22, 4, 180, 0));   // looking away: no sighting
        assertEquals(new Vector2(-27.5, 18), w.ball(), "their corner: our goal line's corner on the ball's side");
        assertEquals(0, w.ballAge(), 1e-9);
        w.update(MjBehaviourTest.at(1.04, "goal_kick_left", -22, 4, 180, 0));
        assertEquals(new Vector2(-25.5, 0), w.ball(), "our goal kick: our goalie area's centre");
        w.update(MjBehaviourTest.at(1.06, "KickIn_Left", -22, 4, 180, 0));
        assertEquals(new Vector2(-25.5, 18), w.ball(), "a kick-in: the touch line at the ball's x (the side of y >= 0)");
        w.update(MjBehaviourTest.at(1.08, "KickOff_Right", -22, 4, 180, 0));
        assertEquals(Vector2.ZERO, w.ball());
        w.update(MjBehaviourTest.at(1.10, "KickOff_Right", -22, 4, 0, 3));
        assertEquals(-19, w.ball().x(), 0.15, "a sighting replaces it (3 m from the camera, 0.11 m ahead of the torso)");
        w.update(MjBehaviourTest.at(1.12, "free_kick_right", -22, 4, 180, 0));
        assertEquals(-19, w.ball().x(), 0.15, "a free kick leaves the ball where it lies");
        // the right team: their own frame is the world turned by 180 deg
        MjWorld r = new MjWorld("Other");
        r.update(MjBehaviourTest.at(1, "PlayOn", 20, -4, 0, 3));   // the ball at world (23, -4): own (-23, 4)
        r.update(MjBehaviourTest.at(1.02, "corner_kick_left", 20, -4, 180, 0));
        assertEquals(new Vector2(-27.5, 18), r.ball(), "their (left's) corner at world (27.5, -18): ours at (-27.5, 18)");
        MjWorld none = new MjWorld("Phalanx");
        none.update(MjBehaviourTest.at(1, "KickIn_Right", -22, 4, 180, 0));
        assertNull(none.ball(), "a kick-in's place needs the ball's x: none without a ball");
    }

    @Test
    void seenPlayersGiveWhoIsAtTheBallAndBadSightingsAreNoSightings() {
        MjWorld w = new MjWorld("Phalanx");
        double x = -10, y = 0;
        List<MjPerception.Seen> seen = List.of(MjKeeperTest.seen("B", x, y, -7, 0, 0.11),
                MjKeeperTest.seen("P Other 4 rfoot", x, y, -6.85, 0.1, 0.05),    // 0.18 m from the ball
                MjKeeperTest.seen("P Other 4 head", x, y, -6.8, 0.1, 1.1),
                MjKeeperTest.seen("P Phalanx 3 lfoot", x, y, -5, 2, 0.05),
                new MjPerception.Seen("P Other 9 lfoot", Double.NaN, 0, 0),     // no polar: no sighting
                new MjPerception.Seen("P Other 8 lfoot", 1e308, 1e308, 1e308),
                new MjPerception.Seen("P", 1, 0, 0), new MjPerception.Seen("P x", 1, 0, 0),  // no team, id or part
                new MjPerception.Seen("B", Double.POSITIVE_INFINITY, 0, 0));
        w.update(MjKeeperTest.view(1, "PlayOn", x, y, Double.NaN, 0));
        w.update(new MjPerception(1.02, 100, "PlayOn", "Phalanx", "Other", 0, 0, new double[] {1, 0, 0, 0}, new double[] {x, y, 0.67},
                null, null, java.util.Map.of("q_hj1", new double[] {0, 0}, "q_hj2", new double[] {0, 0}), java.util.Map.of(), seen, List.of(), 0));
        assertEquals(-7, w.ball().x(), 0.01, "the good ball sighting, not the infinite one");
        assertEquals(2, w.players().size(), "Other 4 and Phalanx 3; the broken ones left out: " + w.players());
        assertTrue(w.otherAtBall(0.3));
        assertFalse(w.otherAtBall(0.1));
        assertEquals(0.18, w.opponentDistance(w.ball()), 0.02);
        assertTrue(w.players().stream().anyMatch(p -> p.mate() && p.id().equals("3")));
        w.update(MjKeeperTest.view(1.04, "PlayOn", x, y, -7, 0));
        assertFalse(w.otherAtBall(0.3), "only this perception's sightings count for at the ball");
        assertEquals(0.18, w.opponentDistance(w.ball()), 0.02, "opponents are remembered 2 s");
        w.update(MjKeeperTest.view(3.1, "PlayOn", x, y, -7, 0));
        assertEquals(Double.POSITIVE_INFINITY, w.opponentDistance(w.ball()), "and then forgotten");
    }
}

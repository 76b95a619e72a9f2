package phalanx.localization.belief;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.Scenes;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.model.robot.NaoModel;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The ball belief falls back on the teammates' reports when the own ball is stale (issue 19, thesis 5.4). */
class BeliefStoreTeamBallTest {
    private static final FieldSpec FIELD = FieldSpec.V066;
    private static final Landmark[] RIGHT_END = {Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R};
    private static final Pose2 TRUTH = new Pose2(-5, 2, 7);
    private static final LocalizationConfig CONFIG = LocalizationConfig.DEFAULT;

    private static BeliefStore located() {
        BeliefStore s = new BeliefStore(FIELD, CONFIG, NaoModel.ofType(0), "Us", null, 0);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        for (int i = 1; i <= 10; i++) s.update(frame(i * 0.06, null));
        assertNotNull(s.belief().self());
        return s;
    }

    /** A vision frame of the right goal's landmarks, with the ball at a field point or no ball. */
    private static Perception frame(double t, Vector2 ball) {
        return Scenes.perception(t, Scenes.vision(Scenes.landmarks(FIELD, Side.LEFT, TRUTH, RIGHT_END),
                ball == null ? null : Scenes.polar(TRUTH, ball.x(), ball.y(), 0.042), List.of()));
    }

    @Test
    void aPlayerThatHasNotSeenTheBallTakesTheTeammatesReport() {
        BeliefStore s = located();
        assertNull(s.belief().ballGlobal(), "never seen");
        // A teammate saw it behind us (outside our view): (-8, 4), said at 0.58.
        s.teamBall(7, new Vector2(-8, 4), 0.58);
        WorldBelief b = s.update(frame(0.66, null));
        assertTrue(b.ballHeard());
        assertEquals(-8, b.ballGlobal().x(), 1e-9);
        assertEquals(4, b.ballGlobal().y(), 1e-9);
        assertEquals(0.08, b.ballAge(), 1e-9, "the report's age");
        assertEquals(TRUTH.toRelative(new Vector2(-8, 4)).x(), b.ballRelative().x(), 0.01, "relative through the own pose");
        assertNull(b.ballVelocity(), "a report carries no velocity");
        assertEquals(1, s.stats().heardBallCycles());
        long stale = s.stats().staleBallCycles();
        assertTrue(stale >= 1, "the heard cycle had a stale own ball");
        // Seen again: own sight wins at once.
        b = s.update(frame(0.72, new Vector2(-3, 3)));
        assertFalse(b.ballHeard());
        assertEquals(stale, s.stats().staleBallCycles(), "seen: not stale");
        assertEquals(-3, b.ballGlobal().x(), 0.01);
    }

    @Test
    void aFreshOwnBallIsKeptAndAnOldReportIsNotUsed() {
        BeliefStore s = located();
        WorldBelief b = s.update(frame(0.66, new Vector2(-3, 3)));
        s.teamBall(7, new Vector2(4, -2), 0.68);
        // Not seen for less than teamBallAfterSeconds (the ball 3 m ahead is in view: keep it out of view instead).
        double t = 0.66 + CONFIG.teamBallAfterSeconds() - 0.1;
        b = s.update(Scenes.perception(t, null));
        assertFalse(b.ballHeard(), "own ball seen " + (t - 0.66) + " s ago");
        assertEquals(-3, b.ballGlobal().x(), 0.01);
        // Stale own ball, but the report is now older than the memory.
        b = s.update(Scenes.perception(0.68 + CONFIG.teamBallMemorySeconds() + 0.02, null));
        assertFalse(b.ballHeard(), "report said " + (CONFIG.teamBallMemorySeconds() + 0.02) + " s ago");
        // A newer report is used.
        s.teamBall(9, new Vector2(4, -2.2), 2.2);
        b = s.update(Scenes.perception(2.24, null));
        assertTrue(b.ballHeard());
        assertEquals(-2.2, b.ballGlobal().y(), 1e-9);
    }

    @Test
    void reportsAreFusedAsThesis54FusesThem() {
        BeliefStore s = located();
        // Three teammates near (2, 1), one far off: the cluster of three weighs 3^3 = 27 against 1.
        s.teamBall(5, new Vector2(2.0, 1.0), 0.6);
        s.teamBall(6, new Vector2(2.2, 1.0), 0.6);
        s.teamBall(8, new Vector2(2.1, 1.3), 0.62);
        s.teamBall(10, new Vector2(-6, -6), 0.62);
        WorldBelief b = s.update(frame(0.66, null));
        double cx = 2.1, cy = 1.1;
        assertEquals((27 * cx - 6) / 28, b.ballGlobal().x(), 1e-9);
        assertEquals((27 * cy - 6) / 28, b.ballGlobal().y(), 1e-9);
        // A teammate's new report replaces his old one.
        s.teamBall(10, new Vector2(2.1, 1.1), 0.7);
        b = s.update(frame(0.72, null));
        assertEquals(2.1, b.ballGlobal().x(), 1e-9);
        assertEquals(0.02, b.ballAge(), 1e-9, "the newest report's age");
    }

    @Test
    void aHeardBallInViewThatIsNotThereIsDropped() {
        int frames = CONFIG.ballMissFrames();
        BeliefStore s = located();
        s.teamBall(4, new Vector2(-2, 1.5), 0.6);    // 3 m ahead: in view
        WorldBelief b = null;
        for (int i = 1; i < frames; i++) b = s.update(frame(0.6 + i * 0.06, null));
        assertTrue(b.ballHeard(), (frames - 1) + " frames without it keep it");
        b = s.update(frame(0.6 + frames * 0.06, null));
        assertFalse(b.ballHeard());
        assertNull(b.ballGlobal());
        assertEquals(1, s.stats().heardBallsMissed());
        // The same report again (said before the drop) stays void; a later one counts.
        s.teamBall(4, new Vector2(-2, 1.5), 0.6);
        assertFalse(s.update(frame(0.6 + (frames + 1) * 0.06, null)).ballHeard());
        s.teamBall(4, new Vector2(-8, 4), 0.9);
        assertTrue(s.update(frame(0.6 + (frames + 2) * 0.06, null)).ballHeard());
    }

    @Test
    void badReportsAreIgnored() {
        BeliefStore s = located();
        s.teamBall(0, new Vector2(1, 1), 0.6);
        s.teamBall(99, new Vector2(1, 1), 0.6);
        s.teamBall(3, null, 0.6);
        s.teamBall(3, new Vector2(Double.NaN, 1), 0.6);
        s.teamBall(3, new Vector2(1, 1), Double.NaN);
        assertFalse(s.update(frame(0.66, null)).ballHeard());
        assertNull(s.belief().ballGlobal());
    }

    @Test
    void offWhenTheOwnBallNeverGoesStale() {
        BeliefStore s = new BeliefStore(FIELD, CONFIG.withTeamBall(Double.POSITIVE_INFINITY, 1.5), NaoModel.ofType(0), "Us", null, 0);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        for (int i = 1; i <= 10; i++) s.update(frame(i * 0.06, null));
        s.teamBall(7, new Vector2(-8, 4), 0.58);
        assertFalse(s.update(frame(0.66, null)).ballHeard());
    }
}

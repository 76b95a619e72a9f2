package phalanx.localization.belief;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.SeenPlayer;
import phalanx.comm.perception.Side;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.Scenes;
import phalanx.model.robot.NaoModel;
import phalanx.localization.fall.FallState;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class BeliefStoreTest {
    private final FieldSpec field = FieldSpec.V066;
    private static final Landmark[] RIGHT_END = {Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R};

    private BeliefStore store(LocalizationConfig.Filter f) {
        return new BeliefStore(field, LocalizationConfig.DEFAULT.withFilter(f), NaoModel.ofType(0), "Us", null, 0);
    }

    private Perception frame(double t, Pose2 truth, Side side, Landmark... seen) {
        return Scenes.perception(t, Scenes.vision(Scenes.landmarks(field, side, truth, seen),
                Scenes.polar(truth, 0, 0, 0.042), List.of()));
    }

    @Test
    void locatesItselfAndTheBallFromExactViews() {
        for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
            BeliefStore s = store(f);
            s.update(Scenes.gameState(0, 3, Side.LEFT));
            Pose2 truth = new Pose2(-5, 2, 7);
            WorldBelief b = null;
            for (int i = 1; i <= 10; i++) b = s.update(frame(i * 0.06, truth, Side.LEFT, RIGHT_END));
            assertEquals(-5, b.self().x(), 0.005, f.name());
            assertEquals(2, b.self().y(), 0.005, f.name());
            assertEquals(7, b.self().thetaDeg(), 0.1, f.name());
            assertEquals(0, b.ballGlobal().norm(), 0.01, f.name());
            assertEquals(truth.toRelative(Vector2.ZERO).x(), b.ballRelative().x(), 0.01);
            assertEquals(0, b.ballVelocity().norm(), 1e-6, "a still ball, ten sightings");
            assertEquals(Side.LEFT, b.side());
            assertEquals(3, b.unum());
            assertEquals(0, b.selfAge(), 1e-9);
            assertEquals(FallState.STANDING, b.fall());
        }
    }

    private Perception frameWithBall(double t, Pose2 truth, double bx, double by) {
        return Scenes.perception(t, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth, RIGHT_END),
                Scenes.polar(truth, bx, by, 0.042), List.of()));
    }

    @Test
    void aBallSeenElsewhereOnceDoesNotRefreshTheOldPlaceAndTwiceInARowMovesTheBelief() {
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 7);
        WorldBelief b = null;
        for (int i = 1; i <= 10; i++) b = s.update(frameWithBall(i * 0.06, truth, 0, 0));
        assertEquals(0, b.ballGlobal().norm(), 0.01);
        // The ball is kicked (or the referee puts it elsewhere): one sighting 3.2 m away is refused by the queue ...
        b = s.update(frameWithBall(0.66, truth, 3, 1));
        assertEquals(0, b.ballGlobal().norm(), 0.01, "one sighting does not move the belief (Algorithm 1)");
        assertEquals(0.06, b.ballAge(), 1e-9, "... and does not pass the old place off as seen just now");
        // ... the second in a row, near the first, relocates the queue there.
        b = s.update(frameWithBall(0.72, truth, 3, 1));
        assertEquals(3, b.ballGlobal().x(), 0.01);
        assertEquals(1, b.ballGlobal().y(), 0.01);
        assertEquals(0, b.ballAge(), 1e-9);
    }

    private Perception frameWithoutBall(double t, Pose2 truth) {
        return Scenes.perception(t, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth, RIGHT_END), null, List.of()));
    }

    /** The server reports every object in its view cone: a believed ball in view that is not seen is not there. */
    @Test
    void aBallNotSeenWhereItIsBelievedInViewIsDroppedAfterBallMissFrames() {
        int frames = LocalizationConfig.DEFAULT.ballMissFrames();
        assertTrue(frames >= 2, "the default needs more than one frame: a single frame may miss");
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 7);
        WorldBelief b = null;
        for (int i = 1; i <= 10; i++) b = s.update(frameWithBall(i * 0.06, truth, -2, 1.5));   // 3 m ahead, in view
        assertNotNull(b.ballGlobal());
        for (int i = 1; i < frames; i++) b = s.update(frameWithoutBall(0.6 + i * 0.06, truth));
        assertNotNull(b.ballGlobal(), (frames - 1) + " frames without it keep the ball");
        b = s.update(frameWithoutBall(0.6 + frames * 0.06, truth));
        assertNull(b.ballGlobal(), "the ball was kicked away: gone after " + frames + " frames");
        assertNull(b.ballRelative());
        assertEquals(1, s.stats().ballsMissed());
        // The next sighting starts the ball again wherever it is.
        b = s.update(frameWithBall(0.6 + (frames + 1) * 0.06, truth, 6, -1));
        assertEquals(6, b.ballGlobal().x(), 0.01);
    }

    @Test
    void aBallOutsideTheViewIsKeptUnseen() {
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 7);
        WorldBelief b = null;
        // 3 m to the robot's left (97° in the field): outside the 120° view of a head turned straight ahead.
        for (int i = 1; i <= 10; i++) b = s.update(frameWithBall(i * 0.06, truth, -5.37, 4.98));
        for (int i = 1; i <= 20; i++) b = s.update(frameWithoutBall(0.6 + i * 0.06, truth));
        assertNotNull(b.ballGlobal(), "not in view, so not seen, and still believed");
        assertEquals(-5.37, b.ballGlobal().x(), 0.02);
        assertEquals(0, s.stats().ballsMissed());
        // Off: the ball in view stays believed however long it is not seen.
        BeliefStore off = new BeliefStore(field, LocalizationConfig.DEFAULT.withBallMiss(0, 50), NaoModel.ofType(0), "Us", null, 0);
        off.update(Scenes.gameState(0, 3, Side.LEFT));
        for (int i = 1; i <= 10; i++) b = off.update(frameWithBall(i * 0.06, truth, -2, 1.5));
        for (int i = 1; i <= 20; i++) b = off.update(frameWithoutBall(0.6 + i * 0.06, truth));
        assertNotNull(b.ballGlobal());
    }

    @Test
    void rightSideBeliefsAreInTheTeamsOwnFrame() {
        BeliefStore s = store(LocalizationConfig.Filter.FIFO);
        s.update(Scenes.gameState(0, 1, Side.RIGHT));
        // S6: field (10, 4) facing -150° is own (-10, -4) facing 30°; the landmarks ahead are F1L, G1L, G2L.
        Pose2 own = new Pose2(-10, -4, 30);
        WorldBelief b = s.update(frame(0.06, own, Side.RIGHT, Landmark.F1L, Landmark.G1L, Landmark.G2L));
        assertEquals(-10, b.self().x(), 0.005);
        assertEquals(-4, b.self().y(), 0.005);
        assertEquals(30, b.self().thetaDeg(), 0.1);
    }

    /** Bad input: no update, no exception, counted. */
    @Test
    void badInputIsCountedAndChangesNothing() throws Exception {
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 2, Side.LEFT));
        Pose2 truth = new Pose2(0, 0, 0);
        s.update(Scenes.perception(0.02, null));                                    // no vision
        s.update(Scenes.perception(0.04, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth), null, List.of())));
        s.update(Scenes.perception(0.06, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth, Landmark.G1R), null, List.of())));
        Polar[] bad = Scenes.landmarks(field, Side.LEFT, truth, Landmark.G1R);
        bad[Landmark.G2R.ordinal()] = new Polar(0, 1, 1);
        bad[Landmark.F1R.ordinal()] = new Polar(Double.NaN, 1, 1);
        bad[Landmark.F2R.ordinal()] = new Polar(-3, 1, 1);
        Polar[] parts = new Polar[BodyPart.COUNT];
        parts[BodyPart.HEAD.ordinal()] = new Polar(2, 0, 0);
        SeenPlayer noId = new SeenPlayer("Them", 0, parts);
        WorldBelief b = s.update(Scenes.perception(0.08, Scenes.vision(bad, new Polar(1, Double.NaN, 0), List.of(noId))));
        assertNull(b.self(), "nothing here makes a fix");
        assertNull(b.ballRelative());
        assertTrue(b.opponents().isEmpty());
        BeliefStats st = s.stats();
        assertEquals(1 + 1, st.noVision(), "the GS message and the blind cycle");
        assertEquals(1, st.noLandmark());
        assertEquals(2, st.oneLandmark(), "G1R alone, and G1R beside three bad ones");
        assertEquals(4, st.badPolar(), "distance 0, NaN, negative and the NaN ball angle");
        assertEquals(1, st.playerWithoutId());
        assertEquals(0, st.selfFixes());
        // A landmark name the server does not have: the parser drops it, the store sees one landmark.
        Perception unknown = new PerceptionParser().parse("(time (now 0.10))(See (F3L (pol 10 0 0)) (G1R (pol 15.0 4.0 -1.0)))");
        assertNull(s.update(unknown).self());
        assertEquals(3, st.oneLandmark());
        assertNull(s.update(null).self());
        // A player seen with no part at all: the snapshot sends "(P (team Them) (id 9))" when only the torso is in view
        // (docs/protocol.md, session 14). It is parsed, and not placed anywhere.
        Perception partless = new PerceptionParser().parse("(time (now 0.12))(See (P (team Them) (id 9)) (G1R (pol 15.0 4.0 -1.0)))");
        assertEquals(1, partless.vision().players().size());
        assertTrue(s.update(partless).opponents().isEmpty());
    }

    @Test
    void seesTeammatesAndOpponentsButNotItsOwnArms() {
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 4, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 0);
        Polar[] own = new Polar[BodyPart.COUNT];
        own[BodyPart.RIGHT_LOWER_ARM.ordinal()] = new Polar(0.18, -34, -24);
        Polar[] mate = new Polar[BodyPart.COUNT];
        mate[BodyPart.HEAD.ordinal()] = Scenes.polar(truth, -3, 2, 0.5);
        Polar[] foe = new Polar[BodyPart.COUNT];
        foe[BodyPart.LEFT_FOOT.ordinal()] = Scenes.polar(truth, -5, 5, 0.0);
        foe[BodyPart.RIGHT_FOOT.ordinal()] = Scenes.polar(truth, -5, 5.2, 0.0);
        List<SeenPlayer> players = List.of(new SeenPlayer("Us", 4, own), new SeenPlayer("Us", 7, mate), new SeenPlayer("Them", 9, foe));
        WorldBelief b = s.update(Scenes.perception(0.06, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth, RIGHT_END), null, players)));
        assertEquals(1, b.teammates().size());
        PlayerBelief m = b.teammates().get(0);
        assertEquals(7, m.id());
        assertEquals(-3, m.global().x(), 0.01);
        assertEquals(2, m.global().y(), 0.01);
        PlayerBelief o = b.opponents().get(0);
        assertEquals(9, o.id());
        assertEquals(5.1, o.global().y(), 0.01, "no head seen: the mean of the feet");
        assertEquals(5.2, o.partGlobal(BodyPart.RIGHT_FOOT).y(), 0.01);
        assertNull(o.partGlobal(BodyPart.HEAD));
    }

    @Test
    void withoutSelfFixObjectsStayRelativeAndOdometryMovesThem() {
        BeliefStore s = store(LocalizationConfig.Filter.FIFO);
        s.update(Scenes.gameState(0, 2, Side.LEFT));
        Pose2 truth = new Pose2(0, 0, 0);
        WorldBelief b = s.update(Scenes.perception(0.06, Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth),
                Scenes.polar(truth, 2, 1, 0.042), List.of())));
        assertNull(b.ballGlobal());
        assertEquals(2, b.ballRelative().x(), 0.01);
        assertEquals(1, b.ballRelative().y(), 0.01);
        s.odometry(0.5, 0, 0);
        b = s.update(Scenes.perception(0.08, null));
        assertEquals(1.5, b.ballRelative().x(), 0.01, "walked half a metre towards it");
        assertEquals(0.02, b.ballAge(), 1e-9);
    }

    @Test
    void noFixWhileAKeyframeMotionMovesTheBody() {
        BeliefStore s = store(LocalizationConfig.Filter.EKF);
        s.update(Scenes.gameState(0, 3, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 7);
        for (int i = 1; i <= 10; i++) s.update(frame(i * 0.06, truth, Side.LEFT, RIGHT_END));
        s.bodyBusy(true);                                     // e.g. a get-up: views from elsewhere are ignored
        WorldBelief b = null;
        for (int i = 11; i <= 20; i++) b = s.update(frame(i * 0.06, new Pose2(8, -3, 100), Side.LEFT, RIGHT_END));
        assertEquals(-5, b.self().x(), 0.005);
        assertEquals(2, b.self().y(), 0.005);
        s.bodyBusy(false);
        for (int i = 21; i <= 40; i++) b = s.update(frame(i * 0.06, new Pose2(8, -3, 100), Side.LEFT, RIGHT_END));
        assertEquals(8, b.self().x(), 0.05, "vision counts again once the motion is over");
    }
}

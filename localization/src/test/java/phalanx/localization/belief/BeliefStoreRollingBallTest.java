package phalanx.localization.belief;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Side;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.Scenes;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.model.robot.NaoModel;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 19 (ball-roll): a ball rolling past at 5 m/s, seen exactly every third cycle. The ball belief is the mean of
 * the queued sightings; moved on with the tracked velocity between sightings it stays on the ball, without it it trails
 * by the queue's age. A ball placed elsewhere (a jump inside the tracker's window, then no motion) is not carried on.
 */
class BeliefStoreRollingBallTest {
    private final FieldSpec field = FieldSpec.V066;
    private static final Landmark[] RIGHT_END = {Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R};
    private static final double DT = 0.02, K = 1.06;
    private static final Pose2 SELF = new Pose2(-5, 2, 0);

    private BeliefStore located(LocalizationConfig config) {
        BeliefStore s = new BeliefStore(field, config, NaoModel.ofType(0), "Us", null, 0);
        s.update(Scenes.gameState(0, 2, Side.LEFT));
        for (int k = 1; k <= 30; k++) see(s, k, new Vector2(-2, 0));
        return s;
    }

    private WorldBelief see(BeliefStore s, int k, Vector2 ball) {
        return s.update(Scenes.perception(k * DT, k % 3 == 0 ? Scenes.vision(Scenes.landmarks(field, Side.LEFT, SELF, RIGHT_END),
                Scenes.polar(SELF, ball.x(), ball.y(), 0.042), List.of()) : null));
    }

    /**
     * The largest ball error over the last 0.6 s of a 1.6 s roll from (-2, 0) along +y at 5 m/s, slowing with the drag
     * (Track Moving Object needs 10 sightings, 0.6 s, before it has a velocity).
     */
    private double rollingError(LocalizationConfig config) {
        BeliefStore s = located(config);
        double worst = 0;
        for (int n = 1; n <= 80; n++) {
            double t = n * DT;
            Vector2 ball = new Vector2(-2, 5 * (1 - Math.exp(-K * t)) / K);
            WorldBelief b = see(s, 30 + n, ball);
            if (n > 50) worst = Math.max(worst, b.ballGlobal().distanceTo(ball));
        }
        return worst;
    }

    @Test
    void aRollingBallIsFollowed() {
        for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
            LocalizationConfig c = LocalizationConfig.DEFAULT.withFilter(f);
            double predicted = rollingError(c);
            double trailing = rollingError(c.withBallPrediction(Double.POSITIVE_INFINITY, K, 0.5, 0.5));
            assertTrue(predicted < 0.08, f + ": predicted " + predicted);
            assertTrue(trailing > 0.3, f + ": without the prediction the mean of the queue trails: " + trailing);
        }
    }

    @Test
    void aPlacedBallIsNotCarriedOn() {
        for (boolean check : new boolean[] {true, false}) {
            LocalizationConfig c = LocalizationConfig.DEFAULT;
            if (!check) c = c.withBallPrediction(0, K, 0, Double.POSITIVE_INFINITY);   // no threshold, any motion agrees
            BeliefStore s = located(c);
            Vector2 placed = new Vector2(-2, 1.5);
            double worst = 0;
            for (int n = 1; n <= 60; n++) {
                WorldBelief b = see(s, 30 + n, placed);
                if (n > 12) worst = Math.max(worst, b.ballGlobal().distanceTo(placed));
            }
            if (check) assertTrue(worst < 0.02, "the placed ball stays where it lies: " + worst);
            else assertTrue(worst > 0.1, "carried on at the jump's speed without the check: " + worst);
        }
    }
}

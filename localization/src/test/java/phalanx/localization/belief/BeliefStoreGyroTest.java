package phalanx.localization.belief;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.Scenes;
import phalanx.model.field.Angles;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.robot.NaoModel;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 19 (turn-head without odometry): the robot turns in place at 60°/s for a second while its frames show one
 * landmark or none, and no odometry is fed. With the gyro's turn (LocalizationConfig.gyroTurn) both filters follow the
 * turn; with the odometry's alone the belief stands still, and the EKF's chi² gate then refuses every single landmark
 * (its heading sigma grows by ekfAngleNoiseDeg per cycle only), so it stays behind.
 */
class BeliefStoreGyroTest {
    private final FieldSpec field = FieldSpec.V066;
    private static final Landmark[] RIGHT_END = {Landmark.F1R, Landmark.G1R, Landmark.G2R, Landmark.F2R};
    private static final double RATE = 60, DT = 0.02;

    private static Perception perception(double t, double gyroZ, phalanx.comm.perception.Vision v) {
        return new Perception(t, null, new Vector3(0, 0, gyroZ), Scenes.UPRIGHT, Scenes.straight(), Scenes.standingFeet(), v,
                List.of(), List.of());
    }

    /** The believed heading minus the true one after the turn, degrees. */
    private double headingErrorAfterTurn(LocalizationConfig config) {
        BeliefStore s = new BeliefStore(field, config, NaoModel.ofType(0), "Us", null, 0);
        s.update(Scenes.gameState(0, 2, Side.LEFT));
        Pose2 truth = new Pose2(-5, 2, 0);
        int k = 1;
        for (; k <= 30; k++) {
            s.update(perception(k * DT, 0, k % 3 == 0 ? Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth, RIGHT_END), null, List.of()) : null));
        }
        assertEquals(0, s.belief().self().thetaDeg(), 0.1, "located before the turn");
        WorldBelief b = null;
        for (int n = 0; n < 50; n++, k++) {
            truth = new Pose2(-5, 2, truth.thetaDeg() + RATE * DT);
            // every third cycle a frame with one landmark (the head sweeping), the goal post ahead-right, else nothing
            b = s.update(perception(k * DT, RATE, k % 3 == 0 ? Scenes.vision(Scenes.landmarks(field, Side.LEFT, truth,
                    n % 2 == 0 ? Landmark.G1R : Landmark.F2R), null, List.of()) : null));
        }
        assertEquals(60, truth.thetaDeg(), 1e-9);
        return Angles.difference(b.self().thetaDeg(), truth.thetaDeg());
    }

    @Test
    void theGyroTurnsTheBeliefBetweenFixes() {
        for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
            LocalizationConfig c = LocalizationConfig.DEFAULT.withFilter(f);
            assertTrue(c.gyroTurn(), "on by default");
            assertEquals(0, headingErrorAfterTurn(c), 0.5, f + " with the gyro");
            double without = headingErrorAfterTurn(c.withGyroTurn(false));
            assertTrue(without < -40, f + " without the gyro or odometry the belief stays behind: " + without);
        }
    }

    @Test
    void theTurnRateIsTheGyroAlongUp() {
        phalanx.localization.body.TiltEstimator t = new phalanx.localization.body.TiltEstimator(0.05, 3);
        t.update(Vector3.ZERO, new Vector3(0, 0, 9.81), DT);
        assertEquals(30, t.turnRateDeg(new Vector3(5, -7, 30)), 1e-9, "upright: the gyro's z");
        assertTrue(Double.isNaN(t.turnRateDeg(null)));
        // lying on its back (up = the torso's -y): a turn about the vertical shows on the gyro's y
        phalanx.localization.body.TiltEstimator back = new phalanx.localization.body.TiltEstimator(0.05, 3);
        back.update(Vector3.ZERO, new Vector3(0, -9.81, 0), DT);
        assertEquals(-20, back.turnRateDeg(new Vector3(0, 20, 3)), 1e-9);
    }
}

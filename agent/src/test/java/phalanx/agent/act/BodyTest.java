package phalanx.agent.act;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.agent.decide.Move;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Vector3;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionLibrary;
import phalanx.motion.control.MotionController;
import phalanx.motion.walk.WalkConfig;

class BodyTest {

    /** An upright robot, all joints at 0 (no toes: type 0); the walk runs open loop, so this is enough. */
    private static Perception standing(double time) {
        double[] deg = new double[Joint.COUNT];
        Arrays.fill(deg, 0);
        deg[Joint.LLJ7.ordinal()] = Double.NaN;
        deg[Joint.RLJ7.ordinal()] = Double.NaN;
        return new Perception(time, null, Vector3.ZERO, new Vector3(0, 0, 9.81), new JointAngles(deg), List.of(), null, List.of(), List.of());
    }

    @Test
    void stepBackWalksBackwardSlowlyAndNeedsNoKeyframeFile() {
        Body body = new Body(new MotionController(MotionLibrary.of(), MotionConfig.DEFAULT), WalkConfig.DEFAULT, MotionConfig.DEFAULT, 0);
        double forward = 0;
        for (int i = 0; i < 100; i++) {
            body.step(standing(i * 0.02), new Move.StepBack());
            forward += body.odometry().forward();
        }
        // 2 s at half the backward limit (0.4 m/s) after the walk's ramp: backward, at most 0.4 m.
        assertTrue(forward < -0.05, "went backward: " + forward);
        assertTrue(forward > -0.2 * 2 - 1e-9, "no faster than half the backward limit: " + forward);
        assertEquals(phalanx.motion.control.MotionRequest.NONE, Locomotion.request(new Move.StepBack()));
    }

    @Test
    void kicksAreRequestedByTheFilesOfTheirFoot() {
        assertEquals("kick", Locomotion.request(new Move.Kick(false, false)).motion());
        assertEquals("strong_kick", Locomotion.request(new Move.Kick(true, false)).motion());
        assertEquals("kick_left", Locomotion.request(new Move.Kick(false, true)).motion());
        assertEquals("strong_kick_left", Locomotion.request(new Move.Kick(true, true)).motion());
    }
}

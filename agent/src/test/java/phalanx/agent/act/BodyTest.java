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

    /** A body whose library holds one short one-phase motion named "kick". */
    private static Body withKick(MotionConfig config) throws Exception {
        String xml = "<motion><phase name=\"A\"><effectors><llj3>10</llj3></effectors><duration>100</duration></phase></motion>";
        var kick = phalanx.motion.phase.PhaseMotionLoader.parse("kick", "kick.xml",
                new java.io.ByteArrayInputStream(xml.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        var quick = phalanx.motion.phase.PhaseMotionLoader.parse("quick_kick", "quick_kick.xml",
                new java.io.ByteArrayInputStream(xml.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        return new Body(new MotionController(MotionLibrary.of(kick, quick), config), WalkConfig.DEFAULT, config, 0);
    }

    /** Cycles from the end of a keyframe "kick" until the walk commands motion, with this settle time. */
    private static int cyclesUntilStepping(double settleSeconds) throws Exception {
        Body body = withKick(MotionConfig.DEFAULT.withStand(0, settleSeconds));
        int i = 0;
        body.step(standing(0), new Move.Kick(false, false));
        while (body.keyframes().playing() != null) body.step(standing(++i * 0.02), Move.STAND);
        for (int n = 0; n < 200; n++) {
            body.step(standing(++i * 0.02), new Move.Walk(0, false));
            if (body.odometry().forward() > 0) return n;
        }
        return -1;
    }

    @Test
    void afterAKeyframeMotionTheWalkStandsForTheSettleTimeBeforeItSteps() throws Exception {
        assertEquals(0, cyclesUntilStepping(0), "no settle time: the walk moves in the first cycle");
        assertEquals(25, cyclesUntilStepping(0.5), "0.5 s: 25 cycles of standing first");
    }

    /** The first walk command of the left knee after a keyframe "kick", the joints read at 0 (the walk stands at about -56). */
    private static double firstKneeCommandAfterKick(double standAfterSeconds) throws Exception {
        Body body = withKick(MotionConfig.DEFAULT.withStand(0, standAfterSeconds));
        int i = 0;
        body.step(standing(0), new Move.Kick(false, false));
        while (body.keyframes().playing() != null) body.step(standing(++i * 0.02), Move.STAND);
        return body.step(standing(++i * 0.02), new Move.Walk(0, false)).radPerSecond(Joint.LLJ4);
    }

    @Test
    void afterAKeyframeMotionTheWalkEasesFromWhereTheMotionLeftTheJointsDuringItsStand() throws Exception {
        assertEquals(-6.1395, firstKneeCommandAfterKick(0), 1e-9, "no stand time: the knee snaps to the walk's crouch at the cap");
        double eased = firstKneeCommandAfterKick(0.4);
        assertTrue(eased < 0 && eased > -0.61, "0.4 s: the first cycle moves the knee a tenth of the cap at most (0.6 % of 56 deg): " + eased);
    }

    /** Cycles between the walk's last step and the start of a kick requested while walking, with this stand time. */
    private static int cyclesStoodBeforeKick(double standSeconds) throws Exception { return cyclesStoodBeforeKick(standSeconds, new Move.Kick(false, false)); }

    private static int cyclesStoodBeforeKick(double standSeconds, Move.Kick k) throws Exception {
        Body body = withKick(MotionConfig.DEFAULT.withStand(standSeconds, 0));
        int i = 0;
        for (; i < 50; i++) body.step(standing(i * 0.02), new Move.Walk(0, false));
        int still = 0;
        for (; i < 300 && body.keyframes().playing() == null; i++) {
            body.step(standing(i * 0.02), k);
            still = body.odometry().equals(phalanx.motion.walk.Odometry.NONE) ? still + 1 : 0;
        }
        return body.keyframes().playing() == null ? -1 : still - 1;   // the cycle the kick started is no stand
    }

    @Test
    void aKickRequestedWhileWalkingStartsOnceTheWalkHasStoppedAndStoodTheStandTime() throws Exception {
        // Odometry is zero once the walk's speed is; the feet then still step back to neutral, so compare the two.
        int none = cyclesStoodBeforeKick(0);
        assertTrue(none >= 0 && none < 25, "no stand time: the kick starts once the walk has stopped: " + none);
        assertEquals(none + 20, cyclesStoodBeforeKick(0.4), "0.4 s: 20 more cycles of standing first");
        assertEquals(none, cyclesStoodBeforeKick(0.4, new Move.Kick(false, false, true)), "the quick kick: no stand time");
    }

    @Test
    void kicksAreRequestedByTheFilesOfTheirFoot() {
        assertEquals("kick", Locomotion.request(new Move.Kick(false, false)).motion());
        assertEquals("strong_kick", Locomotion.request(new Move.Kick(true, false)).motion());
        assertEquals("kick_left", Locomotion.request(new Move.Kick(false, true)).motion());
        assertEquals("strong_kick_left", Locomotion.request(new Move.Kick(true, true)).motion());
        assertEquals("quick_kick", Locomotion.request(new Move.Kick(false, false, true)).motion());
        assertEquals("quick_kick_left", Locomotion.request(new Move.Kick(true, true, true)).motion());
    }
}

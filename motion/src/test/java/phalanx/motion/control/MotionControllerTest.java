package phalanx.motion.control;

import org.junit.jupiter.api.Test;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionLibrary;
import phalanx.motion.phase.PhaseMotion;
import phalanx.motion.phase.PhaseMotionLoader;
import phalanx.motion.webots.TextMotion;
import phalanx.motion.webots.TextMotionLoader;

import java.io.ByteArrayInputStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.*;

/** Drives the controller with synthetic joint readings; every expected number is worked out by hand. */
class MotionControllerTest {
    private static final double EPS = 1e-9;
    private static final MotionConfig THESIS = MotionConfig.DEFAULT.withLatencyCycles(0);

    /** One phase: left hip pitch to 30 deg in 100 ms (5 cycles). */
    private static final String REACH = """
            <motion><phase name="Reach"><effectors><llj3>30</llj3></effectors><duration>100</duration></phase></motion>""";

    /** A cyclic motion: A (2 cycles) -> B (1 cycle) -> A ..., B may finalize to F (1 cycle). */
    private static final String CYCLE = """
            <motion>
              <phase name="A" next="B"><effectors><rlj4>-20</rlj4></effectors><duration>40</duration></phase>
              <phase name="B" next="A"><effectors><rlj4>-15</rlj4></effectors><duration>20</duration><finalize>F</finalize></phase>
              <phase name="F"><effectors><rlj4>-12</rlj4></effectors><duration>20</duration></phase>
            </motion>""";

    /** A walk-like phase in which the left leg swings forward. */
    private static final String SWING = """
            <motion><phase name="L" next="L" swing="left"><effectors><llj3>20</llj3><llj5>-10</llj5><rlj3>20</rlj3></effectors>
            <duration>100</duration><finalize>L2</finalize></phase>
            <phase name="L2"><effectors/><duration>20</duration></phase></motion>""";

    /** Text motion: left hip pitch, five poses (Webots sign: -0.2 rad = +0.2 rad on llj3). */
    private static final String TURN = """
            #WEBOTS_MOTION,V1.0
            LHipPitch
            00:00:000,P1,-0.2
            00:00:040,P2,-0.4
            00:00:080,P3,-0.2
            00:00:120,P4,0
            00:00:160,P5,-0.1
            """;

    static PhaseMotion phase(String name, String xml) throws Exception {
        return PhaseMotionLoader.parse(name, name + ".xml", new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)));
    }

    static TextMotion text(String name, String body) throws Exception {
        return TextMotionLoader.parse(name, name + ".motion", new StringReader(body));
    }

    /** A type 0-3 robot: every joint but the toes at the given angle (deg), others 0. */
    static JointAngles reading(Joint j, double deg) {
        double[] d = new double[Joint.COUNT];
        d[Joint.LLJ7.ordinal()] = Double.NaN;
        d[Joint.RLJ7.ordinal()] = Double.NaN;
        d[j.ordinal()] = deg;
        return new JointAngles(d);
    }

    static MotionController controller(MotionConfig config, Object... motions) {
        phalanx.motion.Motion[] ms = new phalanx.motion.Motion[motions.length];
        for (int i = 0; i < motions.length; i++) ms[i] = (phalanx.motion.Motion) motions[i];
        return new MotionController(MotionLibrary.of(ms), config);
    }

    @Test
    void thesisFormulaTargetMinusCurrentOverPhaseTimeAndZeroForUnlistedJoints() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        JointVelocities v = c.step(10.00, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        assertEquals(Math.toRadians(30) / 0.1, v.radPerSecond(Joint.LLJ3), EPS); // 5.23599 rad/s
        assertEquals(0.0, v.radPerSecond(Joint.RLJ3));
        assertEquals(0.0, v.radPerSecond(Joint.HJ1));
        assertFalse(v.has(Joint.LLJ7), "no toes on this robot: nothing sent");
        assertEquals("reach", c.playing());
        assertEquals("Reach", c.segment());
        // The joint followed: 6 deg after one cycle; 24 deg left in 4 cycles is the same velocity.
        v = c.step(10.02, reading(Joint.LLJ3, 6), MotionRequest.of("reach"));
        assertEquals(Math.toRadians(24) / 0.08, v.radPerSecond(Joint.LLJ3), EPS);
        assertEquals(Math.toRadians(30) / 0.1, v.radPerSecond(Joint.LLJ3), EPS);
        // It lagged (9 deg after two cycles instead of 12): the 3 remaining cycles catch up.
        v = c.step(10.04, reading(Joint.LLJ3, 9), MotionRequest.of("reach"));
        assertEquals(Math.toRadians(21) / 0.06, v.radPerSecond(Joint.LLJ3), EPS);
    }

    @Test
    void velocitiesAreClampedToTheServerCap() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        c.step(0, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        c.step(0.02, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        c.step(0.04, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        // 30 deg in 2 cycles would need 13.09 rad/s.
        JointVelocities v = c.step(0.06, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        assertEquals(6.1395, v.radPerSecond(Joint.LLJ3), EPS);
        v = c.step(0.08, reading(Joint.LLJ3, 90), MotionRequest.of("reach"));
        assertEquals(-6.1395, v.radPerSecond(Joint.LLJ3), EPS);
    }

    @Test
    void latencyCompensationCountsTheCommandAlreadyOnItsWay() throws Exception {
        MotionController c = controller(MotionConfig.DEFAULT, phase("reach", REACH));
        double v0 = Math.toRadians(30) / 0.1;
        assertEquals(v0, c.step(0, reading(Joint.LLJ3, 0), MotionRequest.of("reach")).radPerSecond(Joint.LLJ3), EPS);
        // The first command has not shown yet (reading still 0): it will add v0 * 0.02 s = 6 deg,
        // so 24 deg remain for 4 cycles, the same velocity; without compensation it would be 6.545.
        JointVelocities v = c.step(0.02, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        assertEquals(v0, v.radPerSecond(Joint.LLJ3), EPS);
    }

    @Test
    void continuesCyclesAndFinalizesThroughTheFinalizeLink() throws Exception {
        MotionController c = controller(THESIS, phase("walk", CYCLE));
        MotionRequest walk = MotionRequest.of("walk");
        JointAngles r = reading(Joint.RLJ4, 0);
        c.step(0.00, r, walk);
        assertEquals("A", c.segment());
        // Second cycle of A, the knee at -15: the last -5 deg in the one remaining cycle.
        assertEquals(Math.toRadians(-5) / 0.02, c.step(0.02, reading(Joint.RLJ4, -15), walk).radPerSecond(Joint.RLJ4), EPS);
        assertEquals("A", c.segment());
        JointVelocities v = c.step(0.04, reading(Joint.RLJ4, -20), walk);
        assertEquals("B", c.segment());
        assertEquals(Math.toRadians(5) / 0.02, v.radPerSecond(Joint.RLJ4), EPS);
        c.step(0.06, r, walk);
        assertEquals("A", c.segment(), "still requested: B continues with its next, not its finalize");
        assertFalse(c.finalizing());
        // The request changes while in A: A has no finalize, so it goes on to B ...
        c.step(0.08, r, MotionRequest.NONE);
        assertEquals("A", c.segment());
        c.step(0.10, r, MotionRequest.NONE);
        assertEquals("B", c.segment());
        assertFalse(c.finalizing());
        // ... and B ends in its finalize phase F instead of A.
        v = c.step(0.12, reading(Joint.RLJ4, -10), MotionRequest.NONE);
        assertEquals("F", c.segment());
        assertTrue(c.finalizing());
        assertEquals(Math.toRadians(-2) / 0.02, v.radPerSecond(Joint.RLJ4), EPS);
        assertEquals(0, c.completions());
        // F has no next: the motion has ended, every joint stops.
        v = c.step(0.14, r, MotionRequest.NONE);
        assertNull(c.playing());
        assertEquals(1, c.completions());
        assertEquals("walk", c.lastCompleted());
        for (Joint j : Joint.values()) if (!j.isToe()) assertEquals(0.0, v.radPerSecond(j), j.name());
    }

    @Test
    void aNewRequestStartsInTheCycleTheOldMotionEnds() throws Exception {
        MotionController c = controller(THESIS, phase("walk", CYCLE), phase("reach", REACH));
        JointAngles r = reading(Joint.LLJ3, 0);
        c.step(0.00, r, MotionRequest.of("walk"));   // A
        c.step(0.02, r, MotionRequest.of("reach"));  // A
        assertEquals("walk", c.playing());
        c.step(0.04, r, MotionRequest.of("reach"));  // B
        c.step(0.06, r, MotionRequest.of("reach"));  // F (finalize)
        assertEquals("F", c.segment());
        JointVelocities v = c.step(0.08, r, MotionRequest.of("reach"));
        assertEquals("reach", c.playing());
        assertEquals(Math.toRadians(30) / 0.1, v.radPerSecond(Joint.LLJ3), EPS);
        assertEquals(0.0, v.radPerSecond(Joint.RLJ4), "walk's joint is not listed by reach: stopped");
    }

    @Test
    void interruptAbortsAtOnce() throws Exception {
        MotionController c = controller(THESIS, phase("walk", CYCLE), phase("reach", REACH));
        JointAngles r = reading(Joint.LLJ3, 0);
        c.step(0.00, r, MotionRequest.of("walk"));
        c.step(0.02, r, MotionRequest.of("reach").interrupting());
        assertEquals("reach", c.playing());
        assertEquals(0, c.completions(), "an aborted motion did not complete");
    }

    @Test
    void oneShotMotionCompletesAndRepeatsWhileRequested() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        JointAngles r = reading(Joint.LLJ3, 0);
        for (int k = 0; k < 5; k++) c.step(k * 0.02, r, MotionRequest.of("reach"));
        assertEquals(0, c.completions());
        c.step(0.10, r, MotionRequest.of("reach"));
        assertEquals(1, c.completions());
        assertEquals("reach", c.playing(), "still requested: starts again");
        c.step(0.12, r, MotionRequest.NONE);
        assertEquals("reach", c.playing(), "a one-shot motion plays to its end");
    }

    @Test
    void walkSlowdownStretchesPhasesBy35Percent() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        // 100 ms * 1.35 = 135 ms = 6.75 cycles, rounded to 7.
        JointVelocities v = c.step(0, reading(Joint.LLJ3, 0), MotionRequest.of("reach").slowingDown());
        assertEquals(Math.toRadians(30) / 0.14, v.radPerSecond(Joint.LLJ3), EPS);
        for (int k = 1; k < 7; k++) c.step(k * 0.02, reading(Joint.LLJ3, 0), MotionRequest.NONE);
        assertEquals(0, c.completions());
        c.step(0.14, reading(Joint.LLJ3, 0), MotionRequest.NONE);
        assertEquals(1, c.completions());
    }

    @Test
    void walkLeaningShortensTheLeaningLegsStep() throws Exception {
        MotionController c = controller(THESIS, phase("walk", SWING));
        // lean 0.5 to the left with 8 deg per full lean: llj3 20 -> 16, llj5 -10 -> -6; rlj3 unchanged.
        JointVelocities v = c.step(0, reading(Joint.HJ1, 0), MotionRequest.of("walk").leaning(0.5));
        assertEquals(Math.toRadians(16) / 0.1, v.radPerSecond(Joint.LLJ3), EPS);
        assertEquals(Math.toRadians(-6) / 0.1, v.radPerSecond(Joint.LLJ5), EPS);
        assertEquals(Math.toRadians(20) / 0.1, v.radPerSecond(Joint.RLJ3), EPS);
        // Leaning right changes nothing in a left-swing phase.
        MotionController r = controller(THESIS, phase("walk", SWING));
        v = r.step(0, reading(Joint.HJ1, 0), MotionRequest.of("walk").leaning(-1));
        assertEquals(Math.toRadians(20) / 0.1, v.radPerSecond(Joint.LLJ3), EPS);
    }

    @Test
    void textMotionDurationPoseStepAndTurnGain() throws Exception {
        MotionController c = controller(THESIS, text("turn", TURN));
        MotionRequest turn = MotionRequest.of("turn");
        // Pose P1: llj3 target +0.2 rad, Duration 2 cycles: v = 0.2 / 0.04 = 5 rad/s.
        JointVelocities v = c.step(0, reading(Joint.LLJ3, 0), turn);
        assertEquals(5.0, v.radPerSecond(Joint.LLJ3), EPS);
        assertEquals(0.0, v.radPerSecond(Joint.RLJ3));
        // The divisor stays Duration * cycle (4.5.4), it does not shrink within the pose.
        v = c.step(0.02, reading(Joint.LLJ3, 0), turn);
        assertEquals(5.0, v.radPerSecond(Joint.LLJ3), EPS);
        assertEquals("P1", c.segment());
        v = c.step(0.04, reading(Joint.LLJ3, Math.toDegrees(0.2)), turn.withGain(0.5));
        assertEquals("P2", c.segment());
        assertEquals(0.5 * 0.2 / 0.04, v.radPerSecond(Joint.LLJ3), EPS);
        v = c.step(0.06, reading(Joint.LLJ3, Math.toDegrees(0.2)), turn.withGain(0.05)); // below 0.3: 0.3
        assertEquals(0.3 * 0.2 / 0.04, v.radPerSecond(Joint.LLJ3), EPS);
    }

    @Test
    void textMotionSubsamplesKeepsItsLastPoseAndLoopsWhileRequested() throws Exception {
        MotionController c = controller(THESIS.withTextPose(1, 3), text("turn", TURN));
        JointAngles r = reading(Joint.LLJ3, 0);
        StringBuilder seen = new StringBuilder();
        for (int k = 0; k < 5; k++) {
            c.step(k * 0.02, r, MotionRequest.of("turn"));
            seen.append(c.segment()).append(' ');
        }
        // PoseStep 3 over five poses: P1, P4, then the last pose P5 is not skipped; then it loops.
        assertEquals("P1 P4 P5 P1 P4 ", seen.toString());
        c.step(0.10, r, MotionRequest.NONE);
        assertEquals("P5", c.segment(), "not requested any more: plays on to the last pose");
        assertEquals(0, c.completions());
        c.step(0.12, r, MotionRequest.NONE);
        assertNull(c.playing());
        assertEquals(1, c.completions());
    }

    @Test
    void unknownMotionAndMissingTimeDoNotStopThePlayer() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        JointVelocities v = c.step(0, reading(Joint.LLJ3, 0), MotionRequest.of("moonwalk"));
        assertNull(c.playing());
        assertEquals(0.0, v.radPerSecond(Joint.LLJ3));
        c.step(Double.NaN, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        assertEquals("reach", c.playing());
    }

    @Test
    void aClockThatDoesNotAdvanceCountsAsOneCyclePerStep() throws Exception {
        // A float clock near 2^19 s moves in steps of 1/16 s or not at all: each step is still a cycle.
        MotionController c = controller(THESIS, phase("reach", REACH));
        double t = 524288.0;
        for (int k = 0; k < 5; k++) c.step(t, reading(Joint.LLJ3, 0), MotionRequest.of("reach"));
        assertEquals(0, c.completions());
        c.step(t, reading(Joint.LLJ3, 0), MotionRequest.NONE);
        assertEquals(1, c.completions(), "five cycles of 20 ms: the 100 ms phase is over");
    }

    @Test
    void velocitiesBecomeHingeEffectors() throws Exception {
        MotionController c = controller(THESIS, phase("reach", REACH));
        double[] d = new double[Joint.COUNT];
        java.util.Arrays.fill(d, Double.NaN);
        d[Joint.LLJ3.ordinal()] = 0;
        d[Joint.HJ1.ordinal()] = 5;
        JointVelocities v = c.step(0, new JointAngles(d), MotionRequest.of("reach"));
        assertEquals("(he1 0)(lle3 5.236)", v.appendTo(new EffectorMessage()).toString());
        // The agent's head action may take the head over while the motion plays.
        assertEquals("(he1 -1.5)(lle3 5.236)", v.with(Joint.HJ1, -1.5).appendTo(new EffectorMessage()).toString());
        assertEquals(0.0, v.radPerSecond(Joint.HJ1), "with() leaves the original alone");
    }
}

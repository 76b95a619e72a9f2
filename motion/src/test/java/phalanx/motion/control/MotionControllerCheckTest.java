package phalanx.motion.control;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.motion.MotionConfig;

import static org.junit.jupiter.api.Assertions.*;
import static phalanx.motion.control.MotionControllerTest.controller;
import static phalanx.motion.control.MotionControllerTest.phase;
import static phalanx.motion.control.MotionControllerTest.reading;

/** Torso checks driven with synthetic accelerometer readings (m/s², torso frame: x right, y forward, z up). */
class MotionControllerCheckTest {
    private static final MotionConfig THESIS = MotionConfig.DEFAULT.withLatencyCycles(0);
    private static final Vector3 FACE_DOWN = new Vector3(0, -9.81, 0);   // the forward axis points down
    private static final Vector3 FACE_UP = new Vector3(0, 9.81, 0);
    private static final Vector3 ON_SIDE = new Vector3(9.81, 0.5, 0);
    private static final JointAngles R = reading(Joint.LLJ3, 0);

    /** Rest (1 cycle) checks "chest down"; else back to Flat once, or on to Push. */
    private static final String FRONT = """
            <motion>
              <phase name="Begin" next="Flat"><effectors/><duration>20</duration><finalize>Done</finalize></phase>
              <phase name="Flat" next="Rest"><effectors><llj3>0</llj3></effectors><duration>20</duration></phase>
              <phase name="Rest" next="Push"><effectors><llj3>0</llj3></effectors><duration>20</duration>
                <check axis="forward" max="-0.5" else="Flat"/></phase>
              <phase name="Push" next="Done"><effectors><llj3>10</llj3></effectors><duration>20</duration></phase>
              <phase name="Done"><effectors/><duration>20</duration></phase>
            </motion>""";

    /** Rest switches to the back get-up when the chest faces up. */
    private static final String SWITCHING = """
            <motion>
              <phase name="Rest" next="Push"><effectors><llj3>0</llj3></effectors><duration>20</duration>
                <check axis="forward" max="0.5" switch="back"/></phase>
              <phase name="Push"><effectors><llj3>10</llj3></effectors><duration>20</duration></phase>
            </motion>""";

    private static final String BACK = """
            <motion>
              <phase name="Sit" next="Up"><effectors><llj3>10</llj3></effectors><duration>40</duration></phase>
              <phase name="Up"><effectors><llj3>20</llj3></effectors><duration>20</duration></phase>
            </motion>""";

    @Test
    void aPassingCheckGoesOnToNext() throws Exception {
        MotionController c = controller(THESIS, phase("front", FRONT));
        MotionRequest r = MotionRequest.of("front");
        c.step(0.00, R, FACE_DOWN, r);
        c.step(0.02, R, FACE_DOWN, r);
        c.step(0.04, R, FACE_DOWN, r);
        assertEquals("Rest", c.segment());
        c.step(0.06, R, FACE_DOWN, r);
        assertEquals("Push", c.segment());
    }

    @Test
    void aFailingCheckGoesToItsElsePhaseOncePerPlay() throws Exception {
        MotionController c = controller(THESIS, phase("front", FRONT));
        MotionRequest r = MotionRequest.of("front");
        double t = 0;
        c.step(t, R, ON_SIDE, r);                      // Begin
        c.step(t += 0.02, R, ON_SIDE, r);              // Flat
        c.step(t += 0.02, R, ON_SIDE, r);              // Rest
        assertEquals("Rest", c.segment());
        c.step(t += 0.02, R, ON_SIDE, r);              // on its side: back to Flat
        assertEquals("Flat", c.segment());
        c.step(t += 0.02, R, ON_SIDE, r);
        assertEquals("Rest", c.segment());
        c.step(t += 0.02, R, ON_SIDE, r);              // still on its side, but the else was taken: on
        assertEquals("Push", c.segment());
        c.step(t += 0.02, R, ON_SIDE, r);
        c.step(t += 0.02, R, ON_SIDE, r);
        assertEquals(1, c.completions());
        // requested again, a new play from Begin may take the else again
        assertEquals("Begin", c.segment());
        c.step(t += 0.02, R, ON_SIDE, r);
        c.step(t += 0.02, R, ON_SIDE, r);
        c.step(t += 0.02, R, ON_SIDE, r);
        assertEquals("Flat", c.segment());
    }

    @Test
    void withoutAReadingEveryCheckPasses() throws Exception {
        MotionController c = controller(THESIS, phase("front", FRONT));
        MotionRequest r = MotionRequest.of("front");
        for (int i = 0; i < 4; i++) c.step(i * 0.02, R, r);          // the step without an accelerometer
        assertEquals("Push", c.segment());
        MotionController d = controller(THESIS, phase("front", FRONT));
        Vector3 weightless = new Vector3(0, 0.3, 0);                   // no gravity in it: not a reading
        for (int i = 0; i < 4; i++) d.step(i * 0.02, R, i == 3 ? weightless : null, r);
        assertEquals("Push", d.segment());
    }

    @Test
    void aFailingCheckSwitchesToTheOtherMotionAsTheSameRequest() throws Exception {
        MotionController c = controller(THESIS, phase("front", SWITCHING), phase("back", BACK));
        MotionRequest r = MotionRequest.of("front").interrupting();
        c.step(0.00, R, FACE_UP, r);
        assertEquals("front", c.playing());
        JointVelocities v = c.step(0.02, R, FACE_UP, r);
        assertEquals("back", c.playingMotion());
        assertEquals("front", c.playing(), "still the same request to the agent's one-shot tracking");
        assertEquals("Sit", c.segment());
        assertEquals(Math.toRadians(10) / 0.04, v.radPerSecond(Joint.LLJ3), 1e-9, "the switched motion's first phase plays at once");
        c.step(0.04, R, FACE_UP, r);                   // still requested as "front": not aborted, not finalized
        assertEquals("Sit", c.segment());
        assertFalse(c.finalizing());
        c.step(0.06, R, FACE_UP, r);
        assertEquals("Up", c.segment());
        assertEquals(0, c.completions());
        c.step(0.08, R, FACE_UP, r);
        assertEquals(1, c.completions());
        assertEquals("front", c.lastCompleted(), "the request that ended");
        assertEquals("front", c.playingMotion(), "requested again: the front get-up starts afresh");
    }

    @Test
    void checksAreSkippedWhileFinalizing() throws Exception {
        MotionController c = controller(THESIS, phase("front", SWITCHING), phase("back", BACK));
        c.step(0.00, R, FACE_UP, MotionRequest.of("front"));
        c.step(0.02, R, FACE_UP, MotionRequest.NONE);  // nobody wants it any more: no switch, plays out
        assertEquals("front", c.playing());
        assertEquals("Push", c.segment());
    }
}

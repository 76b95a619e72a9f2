package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.act.Locomotion;
import phalanx.agent.decide.Decision;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.localization.fall.FallState;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionLibrary;
import phalanx.motion.control.MotionController;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Stand Up driving the real motion controller with the project's get-up files: the whole get-up plays,
 * phase after phase, not just its one-cycle Begin (the bug that kept our players lying in games).
 */
class StandUpPlayTest {

    @Test
    void theWholeFrontGetUpPlaysOnceAndThenTheRobotStands() throws Exception {
        MotionLibrary library = MotionLibrary.load(Path.of("motions"));
        MotionController controller = new MotionController(library, MotionConfig.DEFAULT);
        StandUp standUp = new StandUp(AgentConfig.DEFAULT);
        JointAngles joints = new JointAngles(new double[Joint.COUNT]);
        Set<String> phases = new HashSet<>();
        FallState fall = FallState.FALLEN_FRONT;
        int cycles = 0;
        for (; cycles < 400; cycles++) {
            double now = cycles * 0.02;
            World w = World.at(0, 0, 0).fall(fall).time(now)
                    .motion(controller.playing(), controller.lastCompleted(), controller.completions());
            Decision d = standUp.decide(w.situation());
            controller.step(now, joints, Locomotion.request(d.move()));
            if (controller.playing() != null) phases.add(controller.segment());
            if (controller.completions() == 1) fall = FallState.STANDING;  // it stood up at the end
            if (controller.completions() >= 1 && standUp.done(w.situation())) break;
        }
        assertTrue(phases.size() >= 6, "phases played: " + phases);
        assertTrue(cycles * 0.02 > 1.5, "a get-up takes about 2 s, ended after " + cycles * 0.02 + " s");
        assertEquals(1, controller.completions(), "played once, not restarted once standing");
    }

    @Test
    void aFrontGetUpThatFindsTheChestUpSwitchesToTheBackOneAsOnePlay() throws Exception {
        MotionLibrary library = MotionLibrary.load(Path.of("motions"));
        MotionController controller = new MotionController(library, MotionConfig.DEFAULT);
        StandUp standUp = new StandUp(AgentConfig.DEFAULT);
        JointAngles joints = new JointAngles(new double[Joint.COUNT]);
        Vector3 faceUp = new Vector3(0, 9.81, 0);   // rolled onto the back from a side while the limbs settled
        Set<String> motions = new HashSet<>();
        FallState fall = FallState.FALLEN_FRONT;
        int cycles = 0;
        for (; cycles < 400; cycles++) {
            double now = cycles * 0.02;
            World w = World.at(0, 0, 0).fall(fall).time(now)
                    .motion(controller.playing(), controller.lastCompleted(), controller.completions());
            Decision d = standUp.decide(w.situation());
            controller.step(now, joints, faceUp, Locomotion.request(d.move()));
            if (controller.playingMotion() != null) motions.add(controller.playingMotion() + "/" + controller.segment());
            if (controller.completions() == 1) fall = FallState.STANDING;
            if (controller.completions() >= 1 && standUp.done(w.situation())) break;
        }
        assertTrue(motions.contains("stand_up_front/Rest"), "" + motions);
        assertFalse(motions.contains("stand_up_front/ArmsForward"), "switched after Rest: " + motions);
        assertTrue(motions.contains("stand_up_back/Lift"), "the back get-up played on: " + motions);
        assertEquals(1, controller.completions(), "one play: not aborted by the request, not restarted");
        assertEquals("stand_up_front", controller.lastCompleted());
    }
}

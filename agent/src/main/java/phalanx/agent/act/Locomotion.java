package phalanx.agent.act;

import phalanx.agent.decide.Move;
import phalanx.motion.control.MotionRequest;

/**
 * Turns a {@link Move} into the motion controller's request, by the names of the files in
 * {@code motions/} (motions/README.md). The one place that knows those names.
 */
public final class Locomotion {
    private Locomotion() {}

    public static MotionRequest request(Move move) {
        if (move instanceof Move.Walk w) {
            MotionRequest r = MotionRequest.of("walk_forward").leaning(w.lean());
            return w.slow() ? r.slowingDown() : r;
        }
        if (move instanceof Move.Turn t) return MotionRequest.of(t.left() ? "turn_left" : "turn_right").withGain(t.gain());
        if (move instanceof Move.SideStep s) return MotionRequest.of(s.left() ? "side_step_left" : "side_step_right");
        if (move instanceof Move.StepBack) return MotionRequest.NONE; // no keyframe file: only the walk (Body) steps back
        if (move instanceof Move.Kick k) { // literals: no string built in the think cycle
            if (k.quick()) return MotionRequest.of(k.left() ? "quick_kick_left" : "quick_kick");
            return MotionRequest.of(k.strong() ? (k.left() ? "strong_kick_left" : "strong_kick") : (k.left() ? "kick_left" : "kick"));
        }
        if (move instanceof Move.StandUp u) return MotionRequest.of(u.fromFront() ? "stand_up_front" : "stand_up_back").interrupting();
        if (move instanceof Move.Dive d) return MotionRequest.of(d.left() ? "dive_left" : "dive_right").interrupting();
        return MotionRequest.NONE; // Stand
    }
}

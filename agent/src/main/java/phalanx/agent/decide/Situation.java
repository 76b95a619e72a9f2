package phalanx.agent.decide;

import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.PlayMode;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.FieldSpec;

/**
 * Everything an action may read in one cycle: the beliefs, the game, and the motion in progress.
 *
 * @param now        server time (time (now)), seconds
 * @param cycle      this player's cycle count since it connected
 * @param playMode   the current play mode
 * @param gameTime   the game clock, seconds
 * @param belief     the belief store's snapshot
 * @param field      the field of this server version
 * @param joints     the joint angles of this cycle (degrees)
 * @param motion     what the motion controller is doing
 */
public record Situation(double now, long cycle, PlayMode playMode, double gameTime, WorldBelief belief,
                        FieldSpec field, JointAngles joints, MotionStatus motion) {

    /** The motion controller's state, as actions see it. */
    public record MotionStatus(String playing, String lastCompleted, long completions) {
        public static final MotionStatus IDLE = new MotionStatus(null, null, 0);

        public boolean idle() { return playing == null; }
    }
}

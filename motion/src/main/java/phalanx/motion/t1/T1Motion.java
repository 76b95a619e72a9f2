package phalanx.motion.t1;

import java.util.List;

/**
 * A T1 keyframe motion from a Webots text motion file ({@link T1MotionLoader}): the actuators its header names
 * and, per pose, a name, the time it is reached (ms from the start) and each actuator's target in degrees.
 */
public record T1Motion(String name, String source, List<String> actuators, List<String> poseNames, int[] timesMs,
                       double[][] posesDeg) {
    public T1Motion {
        actuators = List.copyOf(actuators);
        poseNames = List.copyOf(poseNames);
        if (posesDeg.length == 0 || posesDeg.length != poseNames.size() || timesMs.length != posesDeg.length)
            throw new IllegalArgumentException("poses, names and times must have the same, non-zero length");
    }

    /** Duration: the last pose's time, s. */
    public double seconds() { return timesMs[timesMs.length - 1] / 1000.0; }
}

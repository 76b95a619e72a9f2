package phalanx.motion.webots;

import phalanx.comm.perception.Joint;
import phalanx.motion.Motion;

import java.util.List;

/**
 * A Webots text motion (4.5.3): one joint set for the whole motion and a list of poses, already
 * converted to the simulator's joints and to degrees. {@code posesDeg[p][k]} is the target of
 * {@code joints().get(k)} in pose p.
 */
public record TextMotion(String name, String source, List<Joint> joints, List<String> poseNames,
                         int[] timesMs, double[][] posesDeg) implements Motion {
    public TextMotion {
        joints = List.copyOf(joints);
        poseNames = List.copyOf(poseNames);
        if (posesDeg.length == 0 || posesDeg.length != poseNames.size() || timesMs.length != posesDeg.length) {
            throw new IllegalArgumentException("poses, names and times must have the same, non-zero length");
        }
    }

    public int poseCount() { return posesDeg.length; }

    /** Target of the k-th header joint in pose p, degrees. */
    public double targetDeg(int pose, int k) { return posesDeg[pose][k]; }
}

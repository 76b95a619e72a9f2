package phalanx.comm.mj;

import java.util.List;
import java.util.Map;

/**
 * One rcssservermj (MuJoCo server) perception. Absent parts are NaN / null / empty.
 * Angles in degrees as sent; quaternion (w, x, y, z).
 */
public record MjPerception(double time, double gameTime, String playMode, String teamLeft, String teamRight,
                           int scoreLeft, int scoreRight, double[] quat, double[] pos, double[] gyro, double[] acc,
                           Map<String, double[]> joints, Map<String, Integer> touch,
                           List<Seen> seen, List<String> heard) {
    /** A seen object: name (marker name, "B", or "P team id part"), polar (distance, azimuth, elevation). */
    public record Seen(String name, double distance, double azimuth, double elevation) {}
}

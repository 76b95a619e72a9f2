package phalanx.comm.mj;

import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * One rcssservermj (MuJoCo server) perception. Absent parts are NaN / null / empty.
 * Angles in degrees as sent; quaternion (w, x, y, z). {@code heard} holds the team-mates' and opponents'
 * messages of this cycle, in the server's order ({@code (MIC hear (AZIMUTH BASE64) ...)}); {@code heardSkipped}
 * counts the pairs that were not an azimuth and valid base64 (skipped, never an exception).
 */
public record MjPerception(double time, double gameTime, String playMode, String teamLeft, String teamRight,
                           int scoreLeft, int scoreRight, double[] quat, double[] pos, double[] gyro, double[] acc,
                           Map<String, double[]> joints, Map<String, Integer> touch,
                           List<Seen> seen, List<Heard> heard, int heardSkipped) {
    /** A seen object: name (marker name, "B", or "P team id part"), polar (distance, azimuth, elevation). */
    public record Seen(String name, double distance, double azimuth, double elevation) {}

    /**
     * A heard message: the azimuth of its source in degrees (microphone frame, counter-clockwise, the server
     * sends whole degrees) and its bytes, base64-decoded (at most 10 from rcsssmj 0.2.1). Compared by content.
     */
    public record Heard(double azimuth, byte[] bytes) {
        public Heard {
            bytes = bytes.clone();
        }

        /** A copy of the message bytes. */
        @Override public byte[] bytes() {
            return bytes.clone();
        }

        @Override public boolean equals(Object o) {
            return o instanceof Heard h && Double.compare(h.azimuth, azimuth) == 0 && Arrays.equals(h.bytes, bytes);
        }

        @Override public int hashCode() {
            return 31 * Double.hashCode(azimuth) + Arrays.hashCode(bytes);
        }

        @Override public String toString() {
            return "Heard[" + azimuth + ", " + java.util.Base64.getEncoder().encodeToString(bytes) + "]";
        }
    }
}

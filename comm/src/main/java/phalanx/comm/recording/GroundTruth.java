package phalanx.comm.recording;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A recording's {@code X_groundtruth.txt} (format in ../shared/recordings/README.md): one line per
 * perceptor message with the torso pose and the ball in the field frame (the left team's frame).
 * Unknown values are NaN.
 */
public final class GroundTruth {
    private GroundTruth() {}

    /**
     * One line. {@code r} is the torso rotation, rows as written (torso-local +x right, +y forward,
     * +z up); {@code yawDeg} is atan2(r22, r12), meaningful while upright.
     */
    public record Line(double now, double x, double y, double z, double[] r, double yawDeg,
                       double ballX, double ballY, double ballZ) {

        public boolean hasTorso() { return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(yawDeg); }
        public boolean hasBall() { return Double.isFinite(ballX) && Double.isFinite(ballY); }

        /** The z component of the torso's up axis: 1 upright, 0 lying. */
        public double upright() { return r[8]; }

        /** Lying or falling: the torso leans more than 45° from vertical. */
        public boolean fallen() { return !(upright() >= Math.cos(Math.toRadians(45))); }
    }

    /** Reads a ground-truth file; a line that cannot be read is an IOException naming file and line. */
    public static List<Line> read(Path file) throws IOException {
        List<String> raw = Files.readAllLines(file, StandardCharsets.US_ASCII);
        List<Line> out = new ArrayList<>(raw.size());
        int n = 0;
        for (String s : raw) {
            n++;
            if (s.isBlank() || s.startsWith("#")) continue;
            String[] f = s.trim().split("\\s+");
            if (f.length != 19) throw new IOException(file + ":" + n + ": expected 19 fields, found " + f.length);
            try {
                double[] r = new double[9];
                for (int i = 0; i < 9; i++) r[i] = num(f[6 + i]);
                out.add(new Line(num(f[0]), num(f[3]), num(f[4]), num(f[5]), r, num(f[15]),
                        num(f[16]), num(f[17]), num(f[18])));
            } catch (NumberFormatException e) {
                throw new IOException(file + ":" + n + ": not a number: " + e.getMessage());
            }
        }
        return out;
    }

    private static double num(String s) {
        return s.equalsIgnoreCase("nan") ? Double.NaN : Double.parseDouble(s);
    }
}

package phalanx.comm.recording;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

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
        List<String> raw = Recordings.lines(file);
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

    /** The header line of a ground-truth file (without the newline). */
    public static final String HEADER = "# now game_time play_mode torso_x torso_y torso_z r11 r12 r13 r21 r22 r23 r31 r32 r33 torso_yaw_deg ball_x ball_y ball_z";

    /**
     * One data line as {@link #read} reads it (the shared recordings' precision: 5 decimals for positions, 6 for R,
     * 3 for the yaw). {@code r} null or a NaN position: the torso fields are {@code nan}; {@code ball} null: the ball's.
     */
    public static String format(double now, double gameTime, String playMode, double x, double y, double z, double[] r,
                                double bx, double by, double bz) {
        StringBuilder sb = new StringBuilder(200);
        sb.append(String.format(Locale.ROOT, "%.2f %s %s", now, gameTime(gameTime), playMode));
        boolean torso = r != null && Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
        if (torso) {
            sb.append(String.format(Locale.ROOT, " %.5f %.5f %.5f", x, y, z));
            for (double v : r) sb.append(String.format(Locale.ROOT, " %.6f", v));
            sb.append(String.format(Locale.ROOT, " %.3f", Math.toDegrees(Math.atan2(r[4], r[1]))));
        } else {
            sb.append(" nan".repeat(13));
        }
        if (Double.isFinite(bx) && Double.isFinite(by)) sb.append(String.format(Locale.ROOT, " %.5f %.5f %.5f", bx, by, bz));
        else sb.append(" nan nan nan");
        return sb.toString();
    }

    /** Game time as the shared recordings write it: "0", "0.16", "12.3". */
    private static String gameTime(double t) {
        if (!Double.isFinite(t)) return "nan";
        String s = String.format(Locale.ROOT, "%.2f", t);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    private static double num(String s) {
        return s.equalsIgnoreCase("nan") ? Double.NaN : Double.parseDouble(s);
    }
}

package phalanx.motion.webots;

import phalanx.comm.perception.Joint;
import phalanx.motion.MotionFileException;
import phalanx.model.robot.JointLimits;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Loads a Webots text motion (4.5.3):
 * <pre>
 * #WEBOTS_MOTION,V1.0                       (the joint header may also follow on this line)
 * LHipYawPitch,LHipRoll,LHipPitch,...       Webots Nao joint names
 * 00:00:000,Pose1,0,-0.012,-0.525,...       time mm:ss:mmm, pose name, radians ('*' = as before)
 * </pre>
 * Lines starting with '#' are comments. Every problem is reported with the file, line, pose and
 * field: a missing magic line, an unknown or repeated joint, a pose with the wrong number of values,
 * a bad time or a time that does not increase, a value that is not a number or is out of range.
 */
public final class TextMotionLoader {
    public static final String MAGIC = "#WEBOTS_MOTION,V1.0";
    private static final Pattern TIME = Pattern.compile("(\\d+):(\\d{1,2}):(\\d{1,3})");

    private TextMotionLoader() {}

    public static TextMotion load(Path file) throws MotionFileException {
        String fileName = file.getFileName().toString();
        int dot = fileName.lastIndexOf('.');
        String name = dot > 0 ? fileName.substring(0, dot) : fileName;
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return parse(name, file.toString(), r);
        } catch (IOException e) {
            throw new MotionFileException(file.toString(), 0, null, null, "cannot read: " + e.getMessage(), e);
        }
    }

    public static TextMotion parse(String name, String source, Reader reader) throws MotionFileException, IOException {
        Table<Joint> t = read(source, reader, n -> {
            WebotsJoints.Mapping m = WebotsJoints.byWebotsName(n);
            return m == null ? null : new Column<>(m.joint(), m.sign(), m.joint().perceptorName(),
                    JointLimits.minDeg(m.joint()), JointLimits.maxDeg(m.joint()));
        }, WebotsJoints.names().toString());
        return new TextMotion(name, source, t.joints(), t.poseNames(), t.timesMs(), t.posesDeg());
    }

    /**
     * A header name resolved to a robot's joint: the joint, the sign that turns the file's angle into the
     * simulator's, the name errors give for it, and its range on the simulator in degrees.
     */
    public record Column<J>(J joint, int sign, String field, double minDeg, double maxDeg) {}

    /** A parsed motion table: the header's joints, and per pose its name, time (ms) and targets (degrees). */
    public record Table<J>(List<J> joints, List<String> poseNames, int[] timesMs, double[][] posesDeg) {}

    /**
     * Reads a Webots text motion for any robot: {@code columns} resolves a header name (null: unknown, and
     * {@code known} lists the names in the error). Used for the Nao here and for the T1 (motion.t1.T1MotionLoader).
     */
    public static <J> Table<J> read(String source, Reader reader, Function<String, Column<J>> columns, String known)
            throws MotionFileException, IOException {
        BufferedReader in = reader instanceof BufferedReader b ? b : new BufferedReader(reader);
        String line = in.readLine();
        int lineNo = 1;
        if (line == null) throw new MotionFileException(source, 0, null, "header", "empty file: the first line must be " + MAGIC, null);
        if (line.startsWith("\uFEFF")) line = line.substring(1);
        if (!line.strip().startsWith(MAGIC)) {
            throw new MotionFileException(source, 1, null, "header", "the first line must be " + MAGIC + ", found '" + abbreviate(line) + "'", null);
        }
        String headerRest = line.strip().substring(MAGIC.length());
        List<Column<J>> header = null;
        if (!headerRest.isEmpty()) {
            if (headerRest.charAt(0) != ',') throw new MotionFileException(source, 1, null, "header", "expected ',' after " + MAGIC, null);
            header = header(source, 1, headerRest.substring(1), columns, known);
        }

        List<String> poseNames = new ArrayList<>();
        List<Integer> times = new ArrayList<>();
        List<double[]> poses = new ArrayList<>();
        while ((line = in.readLine()) != null) {
            lineNo++;
            String s = line.strip();
            if (s.isEmpty() || s.startsWith("#")) continue;
            if (header == null) {
                header = header(source, lineNo, s, columns, known);
                continue;
            }
            String[] f = s.split(",", -1);
            String poseName = f.length > 1 ? f[1].strip() : "#" + (poses.size() + 1);
            String part = "pose '" + poseName + "'";
            if (f.length != header.size() + 2) {
                throw new MotionFileException(source, lineNo, part, null, "has " + Math.max(0, f.length - 2) + " joint values, the header lists " + header.size(), null);
            }
            int t = time(source, lineNo, part, f[0].strip());
            if (!times.isEmpty() && t <= times.get(times.size() - 1)) {
                throw new MotionFileException(source, lineNo, part, "time", f[0].strip() + " does not come after the previous pose's time", null);
            }
            double[] pose = new double[header.size()];
            for (int k = 0; k < header.size(); k++) {
                Column<J> c = header.get(k);
                String v = f[k + 2].strip();
                if (v.equals("*")) {
                    if (poses.isEmpty()) throw new MotionFileException(source, lineNo, part, c.field(), "'*' (unchanged) needs an earlier pose", null);
                    pose[k] = poses.get(poses.size() - 1)[k];
                    continue;
                }
                double rad;
                try {
                    rad = Double.parseDouble(v);
                } catch (NumberFormatException e) {
                    throw new MotionFileException(source, lineNo, part, c.field(), "'" + v + "' is not a number of radians", null);
                }
                if (!Double.isFinite(rad)) throw new MotionFileException(source, lineNo, part, c.field(), "'" + v + "' is not finite", null);
                double deg = c.sign() * Math.toDegrees(rad);
                if (deg < c.minDeg() - 1e-9 || deg > c.maxDeg() + 1e-9) {
                    throw new MotionFileException(source, lineNo, part, c.field(), v + " rad is " + round(deg) + " deg on the simulator's joint, outside its range ["
                            + round(c.minDeg()) + ", " + round(c.maxDeg()) + "]", null);
                }
                pose[k] = deg;
            }
            poseNames.add(poseName);
            times.add(t);
            poses.add(pose);
        }
        if (header == null) throw new MotionFileException(source, lineNo, null, "header", "no joint header line", null);
        if (poses.isEmpty()) throw new MotionFileException(source, lineNo, null, "poses", "no pose lines", null);
        return new Table<>(header.stream().map(Column::joint).toList(), poseNames,
                times.stream().mapToInt(Integer::intValue).toArray(), poses.toArray(new double[0][]));
    }

    private static <J> List<Column<J>> header(String source, int lineNo, String text, Function<String, Column<J>> columns, String known)
            throws MotionFileException {
        List<Column<J>> out = new ArrayList<>();
        Set<J> seen = new HashSet<>();
        for (String raw : text.split(",", -1)) {
            String n = raw.strip();
            if (n.isEmpty()) throw new MotionFileException(source, lineNo, null, "header", "empty joint name in the header", null);
            Column<J> c = columns.apply(n);
            if (c == null) throw new MotionFileException(source, lineNo, null, "header/" + n, "unknown joint '" + n + "' (known: " + known + ")", null);
            if (!seen.add(c.joint())) throw new MotionFileException(source, lineNo, null, "header/" + n, "joint listed twice", null);
            out.add(c);
        }
        return out;
    }

    private static int time(String source, int lineNo, String part, String s) throws MotionFileException {
        Matcher m = TIME.matcher(s);
        if (!m.matches()) throw new MotionFileException(source, lineNo, part, "time", "'" + s + "' is not mm:ss:mmm", null);
        int sec = Integer.parseInt(m.group(2));
        if (sec >= 60) throw new MotionFileException(source, lineNo, part, "time", "'" + s + "' has " + sec + " seconds", null);
        return Integer.parseInt(m.group(1)) * 60_000 + sec * 1000 + Integer.parseInt(m.group(3));
    }

    private static String abbreviate(String s) { return s.length() > 40 ? s.substring(0, 40) + "..." : s; }
    private static double round(double d) { return Math.round(d * 100) / 100.0; }
}

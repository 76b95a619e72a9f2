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
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
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
        BufferedReader in = reader instanceof BufferedReader b ? b : new BufferedReader(reader);
        String line = in.readLine();
        int lineNo = 1;
        if (line == null) throw new MotionFileException(source, 0, null, "header", "empty file: the first line must be " + MAGIC, null);
        if (line.startsWith("\uFEFF")) line = line.substring(1);
        if (!line.strip().startsWith(MAGIC)) {
            throw new MotionFileException(source, 1, null, "header", "the first line must be " + MAGIC + ", found '" + abbreviate(line) + "'", null);
        }
        String headerRest = line.strip().substring(MAGIC.length());
        List<Joint> joints = null;
        List<Integer> signs = new ArrayList<>();
        if (!headerRest.isEmpty()) {
            if (headerRest.charAt(0) != ',') throw new MotionFileException(source, 1, null, "header", "expected ',' after " + MAGIC, null);
            joints = header(source, 1, headerRest.substring(1), signs);
        }

        List<String> poseNames = new ArrayList<>();
        List<Integer> times = new ArrayList<>();
        List<double[]> poses = new ArrayList<>();
        while ((line = in.readLine()) != null) {
            lineNo++;
            String s = line.strip();
            if (s.isEmpty() || s.startsWith("#")) continue;
            if (joints == null) {
                joints = header(source, lineNo, s, signs);
                continue;
            }
            String[] f = s.split(",", -1);
            String poseName = f.length > 1 ? f[1].strip() : "#" + (poses.size() + 1);
            String part = "pose '" + poseName + "'";
            if (f.length != joints.size() + 2) {
                throw new MotionFileException(source, lineNo, part, null, "has " + Math.max(0, f.length - 2) + " joint values, the header lists " + joints.size(), null);
            }
            int t = time(source, lineNo, part, f[0].strip());
            if (!times.isEmpty() && t <= times.get(times.size() - 1)) {
                throw new MotionFileException(source, lineNo, part, "time", f[0].strip() + " does not come after the previous pose's time", null);
            }
            double[] pose = new double[joints.size()];
            for (int k = 0; k < joints.size(); k++) {
                Joint j = joints.get(k);
                String field = j.perceptorName();
                String v = f[k + 2].strip();
                if (v.equals("*")) {
                    if (poses.isEmpty()) throw new MotionFileException(source, lineNo, part, field, "'*' (unchanged) needs an earlier pose", null);
                    pose[k] = poses.get(poses.size() - 1)[k];
                    continue;
                }
                double rad;
                try {
                    rad = Double.parseDouble(v);
                } catch (NumberFormatException e) {
                    throw new MotionFileException(source, lineNo, part, field, "'" + v + "' is not a number of radians", null);
                }
                if (!Double.isFinite(rad)) throw new MotionFileException(source, lineNo, part, field, "'" + v + "' is not finite", null);
                double deg = signs.get(k) * Math.toDegrees(rad);
                if (!JointLimits.contains(j, deg)) {
                    throw new MotionFileException(source, lineNo, part, field, v + " rad is " + round(deg) + " deg on the simulator's joint, outside its range ["
                            + JointLimits.minDeg(j) + ", " + JointLimits.maxDeg(j) + "]", null);
                }
                pose[k] = deg;
            }
            poseNames.add(poseName);
            times.add(t);
            poses.add(pose);
        }
        if (joints == null) throw new MotionFileException(source, lineNo, null, "header", "no joint header line", null);
        if (poses.isEmpty()) throw new MotionFileException(source, lineNo, null, "poses", "no pose lines", null);
        return new TextMotion(name, source, joints, poseNames, times.stream().mapToInt(Integer::intValue).toArray(), poses.toArray(new double[0][]));
    }

    private static List<Joint> header(String source, int lineNo, String text, List<Integer> signs) throws MotionFileException {
        List<Joint> joints = new ArrayList<>();
        Set<Joint> seen = EnumSet.noneOf(Joint.class);
        for (String raw : text.split(",", -1)) {
            String n = raw.strip();
            if (n.isEmpty()) throw new MotionFileException(source, lineNo, null, "header", "empty joint name in the header", null);
            WebotsJoints.Mapping m = WebotsJoints.byWebotsName(n);
            if (m == null) throw new MotionFileException(source, lineNo, null, "header/" + n, "unknown joint '" + n + "' (known: " + WebotsJoints.names() + ")", null);
            if (!seen.add(m.joint())) throw new MotionFileException(source, lineNo, null, "header/" + n, "joint listed twice", null);
            joints.add(m.joint());
            signs.add(m.sign());
        }
        return joints;
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

package phalanx.motion.t1;

import phalanx.model.robot.T1Joints;
import phalanx.motion.MotionFileException;
import phalanx.motion.webots.TextMotionLoader;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Loads a T1 keyframe motion in the thesis's Webots text format (4.5.3, {@link TextMotionLoader}): the header
 * names T1 joints as robot.xml does ({@code Left_Hip_Pitch}, ...; model/robots/t1-joints.tsv), the values are
 * radians in robot.xml's convention, checked against the joint's range.
 */
public final class T1MotionLoader {
    private T1MotionLoader() {}

    public static T1Motion load(Path file) throws MotionFileException {
        String fileName = file.getFileName().toString();
        int dot = fileName.lastIndexOf('.');
        try {
            return parse(dot > 0 ? fileName.substring(0, dot) : fileName, file.toString(), Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new MotionFileException(file.toString(), 0, null, null, "cannot read: " + e.getMessage(), e);
        }
    }

    public static T1Motion parse(String name, String source, String text) throws MotionFileException {
        try (Reader r = new StringReader(text)) {
            TextMotionLoader.Table<String> t = TextMotionLoader.read(source, r, n -> {
                T1Joints.T1Joint j = T1Joints.ALL.stream().filter(x -> x.joint().equals(n)).findFirst().orElse(null);
                return j == null ? null : new TextMotionLoader.Column<>(j.actuator(), 1, j.joint(), Math.toDegrees(j.minRad()), Math.toDegrees(j.maxRad()));
            }, T1Joints.ALL.stream().map(T1Joints.T1Joint::joint).toList().toString());
            return new T1Motion(name, source, t.joints(), t.poseNames(), t.timesMs(), t.posesDeg());
        } catch (IOException e) {
            throw new MotionFileException(source, 0, null, null, "cannot read: " + e.getMessage(), e);
        }
    }
}

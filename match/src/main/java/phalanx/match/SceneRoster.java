package phalanx.match;

import phalanx.comm.perception.Side;

import java.util.Optional;
import java.util.SortedSet;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The robots on the field, read from a full scene graph ({@code (RSG …)}) of the monitor stream.
 * The server sends a full scene when the monitor connects and whenever the scene changes (a robot
 * created or removed); every robot's body mesh carries {@code (resetMaterials matNum<unum> matLeft|matRight …)}.
 * Partial updates ({@code (RDS …)}) do not name robots, so they say nothing about the roster.
 */
public final class SceneRoster {
    private static final Pattern BODY = Pattern.compile("\\(resetMaterials matNum(\\d+) mat(Left|Right)\\b");

    private SceneRoster() { }

    /** One robot: its team's side and its uniform number. */
    public record Robot(Side side, int unum) implements Comparable<Robot> {
        @Override public int compareTo(Robot o) {
            int c = side.compareTo(o.side);
            return c != 0 ? c : Integer.compare(unum, o.unum);
        }
    }

    /** The robots in this message if it is a full scene, empty for a partial update or anything else. */
    public static Optional<SortedSet<Robot>> of(String monitorMessage) {
        int rsg = monitorMessage.indexOf("(RSG ");
        int rds = monitorMessage.indexOf("(RDS ");
        if (rsg < 0 || (rds >= 0 && rds < rsg)) return Optional.empty();
        SortedSet<Robot> robots = new TreeSet<>();
        Matcher m = BODY.matcher(monitorMessage);
        m.region(rsg, monitorMessage.length());
        while (m.find()) {
            try {
                robots.add(new Robot(m.group(2).equals("Left") ? Side.LEFT : Side.RIGHT, Integer.parseInt(m.group(1))));
            } catch (NumberFormatException e) {
                // a uniform number too long for an int is not a robot of ours to count
            }
        }
        return Optional.of(robots);
    }
}

package phalanx.model.robot;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** The Booster T1's 23 joints (robots/t1-joints.tsv): perceptor, actuator, range, torque limit. */
public final class T1Joints {
    /** One joint; the range in radians, the torque limit in N m. */
    public record T1Joint(String perceptor, String actuator, String joint, double minRad, double maxRad, double torque) {
        public boolean contains(double rad) { return rad >= minRad && rad <= maxRad; }
        public double clampDeg(double deg) {
            return Math.max(Math.toDegrees(minRad), Math.min(Math.toDegrees(maxRad), deg));
        }
    }

    public static final List<T1Joint> ALL = load();

    private T1Joints() {}

    private static List<T1Joint> load() {
        RobotTable t = RobotTable.load("t1-joints.tsv", 6);
        List<T1Joint> out = new ArrayList<>();
        for (int i = 0; i < t.size(); i++) {
            out.add(new T1Joint(t.text(i, 0), t.text(i, 1), t.text(i, 2), t.number(i, 3), t.number(i, 4), t.number(i, 5)));
        }
        return Collections.unmodifiableList(out);
    }

    /** The joint driven by this actuator, or null. */
    public static T1Joint byActuator(String actuator) {
        for (T1Joint j : ALL) if (j.actuator().equals(actuator)) return j;
        return null;
    }

    /** The actuator names in table order. */
    public static List<String> actuators() {
        return ALL.stream().map(T1Joint::actuator).toList();
    }
}

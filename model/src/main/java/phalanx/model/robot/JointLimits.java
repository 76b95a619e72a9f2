package phalanx.model.robot;

import phalanx.comm.perception.Joint;

/**
 * Hinge ranges in degrees as the server's Nao model defines them (the same for all five robot
 * types; the toes' range is not in our notes, so they get a wide one). Motion files are checked
 * against these at load time: a target the joint cannot reach is a mistake in the file.
 */
public final class JointLimits {
    private static final double[] MIN = new double[Joint.COUNT];
    private static final double[] MAX = new double[Joint.COUNT];

    static {
        RobotTable t = RobotTable.load("nao-joints.tsv", 3);
        for (int i = 0; i < t.size(); i++) {
            Joint j = Joint.byName(t.text(i, 0));
            if (j == null) throw new IllegalStateException("robot table nao-joints.tsv: unknown joint " + t.text(i, 0));
            set(j, t.number(i, 1), t.number(i, 2));
        }
    }

    private JointLimits() {}

    private static void set(Joint j, double min, double max) {
        MIN[j.ordinal()] = min;
        MAX[j.ordinal()] = max;
    }

    public static double minDeg(Joint j) { return MIN[j.ordinal()]; }
    public static double maxDeg(Joint j) { return MAX[j.ordinal()]; }
    public static boolean contains(Joint j, double deg) { return deg >= MIN[j.ordinal()] && deg <= MAX[j.ordinal()]; }
    public static double clamp(Joint j, double deg) { return Math.max(MIN[j.ordinal()], Math.min(MAX[j.ordinal()], deg)); }
}

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
        set(Joint.HJ1, -120, 120); set(Joint.HJ2, -45, 45);
        set(Joint.LAJ1, -120, 120); set(Joint.RAJ1, -120, 120);
        set(Joint.LAJ2, -1, 95); set(Joint.RAJ2, -95, 1);
        set(Joint.LAJ3, -120, 120); set(Joint.RAJ3, -120, 120);
        set(Joint.LAJ4, -90, 1); set(Joint.RAJ4, -1, 90);
        set(Joint.LLJ1, -90, 1); set(Joint.RLJ1, -90, 1);
        set(Joint.LLJ2, -25, 45); set(Joint.RLJ2, -45, 25);
        set(Joint.LLJ3, -25, 100); set(Joint.RLJ3, -25, 100);
        set(Joint.LLJ4, -130, 1); set(Joint.RLJ4, -130, 1);
        set(Joint.LLJ5, -45, 75); set(Joint.RLJ5, -45, 75);
        set(Joint.LLJ6, -45, 25); set(Joint.RLJ6, -25, 45);
        set(Joint.LLJ7, -90, 90); set(Joint.RLJ7, -90, 90);
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

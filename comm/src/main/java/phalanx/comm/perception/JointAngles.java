package phalanx.comm.perception;

import java.util.Arrays;

/** Joint angles in degrees from the HJ perceptors of one message; NaN for a joint not reported. */
public final class JointAngles {
    private final double[] degrees;

    public JointAngles(double[] degrees) {
        if (degrees.length != Joint.COUNT) throw new IllegalArgumentException("need " + Joint.COUNT + " angles");
        this.degrees = degrees;
    }

    public static JointAngles none() {
        double[] d = new double[Joint.COUNT];
        Arrays.fill(d, Double.NaN);
        return new JointAngles(d);
    }

    public double degrees(Joint j) { return degrees[j.ordinal()]; }
    public double radians(Joint j) { return Math.toRadians(degrees[j.ordinal()]); }
    public boolean has(Joint j) { return !Double.isNaN(degrees[j.ordinal()]); }

    /** A copy of the raw array, indexed by {@link Joint#ordinal()}. */
    public double[] toArray() { return degrees.clone(); }

    @Override public boolean equals(Object o) {
        return o instanceof JointAngles other && Arrays.equals(degrees, other.degrees);
    }
    @Override public int hashCode() { return Arrays.hashCode(degrees); }
    @Override public String toString() {
        StringBuilder sb = new StringBuilder("JointAngles[");
        for (Joint j : Joint.values()) if (has(j)) sb.append(j.perceptorName()).append('=').append(degrees(j)).append(' ');
        return sb.append(']').toString();
    }
}

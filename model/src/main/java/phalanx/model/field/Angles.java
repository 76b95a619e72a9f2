package phalanx.model.field;

/** Angle arithmetic in degrees. */
public final class Angles {
    private Angles() {}

    /** The same angle in (-180, 180]. */
    public static double normalize(double degrees) {
        double a = Math.IEEEremainder(degrees, 360.0);
        return a == -180.0 ? 180.0 : a;
    }

    /** The signed smallest difference a - b, in (-180, 180]. */
    public static double difference(double a, double b) { return normalize(a - b); }
}

package phalanx.model.field;

/** A point or direction on the ground plane, metres. */
public record Vector2(double x, double y) {
    public static final Vector2 ZERO = new Vector2(0, 0);

    /** The unit vector at this angle (degrees, counter-clockwise from +x). */
    public static Vector2 ofAngle(double degrees) {
        double r = Math.toRadians(degrees);
        return new Vector2(Math.cos(r), Math.sin(r));
    }

    /** ofAngle(degrees).times(length), in one allocation. */
    public static Vector2 polar(double length, double degrees) {
        double r = Math.toRadians(degrees);
        return new Vector2(Math.cos(r) * length, Math.sin(r) * length);
    }

    public Vector2 plus(Vector2 o) { return new Vector2(x + o.x, y + o.y); }
    public Vector2 minus(Vector2 o) { return new Vector2(x - o.x, y - o.y); }
    public Vector2 times(double k) { return new Vector2(x * k, y * k); }
    public double dot(Vector2 o) { return x * o.x + y * o.y; }
    public double cross(Vector2 o) { return x * o.y - y * o.x; }
    public double norm() { return Math.hypot(x, y); }
    public double distanceTo(Vector2 o) { return Math.hypot(x - o.x, y - o.y); }
    /** Angle of this vector in degrees, (-180, 180]. */
    public double angleDeg() { return Math.toDegrees(Math.atan2(y, x)); }
    /** This vector turned counter-clockwise by the given degrees. */
    public Vector2 rotate(double degrees) {
        double r = Math.toRadians(degrees), c = Math.cos(r), s = Math.sin(r);
        return new Vector2(c * x - s * y, s * x + c * y);
    }
    public boolean isFinite() { return Double.isFinite(x) && Double.isFinite(y); }
}

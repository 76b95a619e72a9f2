package phalanx.comm.perception;

/** A 3D vector: the one vector type shared by every module (gyro, accelerometer, positions). */
public record Vector3(double x, double y, double z) {
    public static final Vector3 ZERO = new Vector3(0, 0, 0);

    public Vector3 plus(Vector3 o) { return new Vector3(x + o.x, y + o.y, z + o.z); }
    public Vector3 minus(Vector3 o) { return new Vector3(x - o.x, y - o.y, z - o.z); }
    public Vector3 times(double k) { return new Vector3(x * k, y * k, z * k); }
    public double dot(Vector3 o) { return x * o.x + y * o.y + z * o.z; }
    public double norm() { return Math.sqrt(x * x + y * y + z * z); }
    public boolean isFinite() { return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z); }
}

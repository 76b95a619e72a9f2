package phalanx.comm.perception;

/**
 * One vision observation, as the server sends it: distance in metres, horizontal and vertical
 * angle in degrees, relative to the camera (thesis 3.5.2; positive horizontal is to the left).
 */
public record Polar(double distance, double horizontalDeg, double verticalDeg) {

    /** True when every component is a finite number and the distance is positive. */
    public boolean isUsable() {
        return distance > 0 && Double.isFinite(distance)
                && Double.isFinite(horizontalDeg) && Double.isFinite(verticalDeg);
    }

    /** Cartesian camera-frame vector: +x straight ahead of the camera, +y left, +z up. */
    public Vector3 toCartesian() {
        double h = Math.toRadians(horizontalDeg), v = Math.toRadians(verticalDeg);
        double c = Math.cos(v);
        return new Vector3(distance * c * Math.cos(h), distance * c * Math.sin(h), distance * Math.sin(v));
    }
}

package phalanx.coordination.features;

import phalanx.coordination.CoordinationConfig.CollisionConfig;

/**
 * The potential-collision feature (thesis 5.8, Figure 5.8). Each route is the straight segment from a
 * player's position to its target. Routes that do not cross cost 0; routes that cross cost
 * {@code likely} (100) when the crossing point is about as far from both starts (|d1 − d2| within
 * {@code equidistance}, 1.5 m), as the two players would reach it together, and {@code unlikely} (2)
 * otherwise. Parallel routes and routes of zero length never cross.
 */
public final class RouteCollision {
    private RouteCollision() {}

    /** The cost of routes (ax,ay)→(bx,by) and (cx,cy)→(dx,dy). */
    public static double cost(double ax, double ay, double bx, double by,
                              double cx, double cy, double dx, double dy, CollisionConfig c) {
        double rx = bx - ax, ry = by - ay, sx = dx - cx, sy = dy - cy;
        double denom = rx * sy - ry * sx;
        if (denom == 0) return 0;
        double qx = cx - ax, qy = cy - ay;
        double t = (qx * sy - qy * sx) / denom;
        double u = (qx * ry - qy * rx) / denom;
        if (t < 0 || t > 1 || u < 0 || u > 1) return 0;
        double d1 = t * Math.hypot(rx, ry), d2 = u * Math.hypot(sx, sy);
        return Math.abs(d1 - d2) <= c.equidistance() ? c.likely() : c.unlikely();
    }

    /** True when the two routes cross (whatever the cost). */
    public static boolean crosses(double ax, double ay, double bx, double by,
                                  double cx, double cy, double dx, double dy) {
        return cost(ax, ay, bx, by, cx, cy, dx, dy, ANY) != 0;
    }

    private static final CollisionConfig ANY = new CollisionConfig(1, 1, 0);
}

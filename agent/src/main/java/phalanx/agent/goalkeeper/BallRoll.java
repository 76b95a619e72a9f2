package phalanx.agent.goalkeeper;

import phalanx.model.field.Vector2;

/**
 * Where and when a rolling ball crosses the goalkeeper's Y axis (thesis 5.13, Figure 5.15), with
 * the server's ball friction. SimSpark's ball (rsg/agent/ball.rsg) has no rolling resistance, only
 * a DragController: a force −0.01·v (N) and a torque −0.00005·ω (N·m) on a 0.026 kg sphere of
 * radius 0.042 m. For a ball rolling without slipping (ω = v/r, I = 2/5·m·r²) that is
 * (7/5)·m·dv/dt = −(0.01 + 0.00005/r²)·v, i.e. dv/dt = −k·v with k = 1.05 /s (a sliding ball
 * would have 0.385 /s). So v(t) = v0·e^(−k·t), the path stays straight, and the distance covered
 * is s(t) = v0·(1 − e^(−k·t))/k, at most v0/k. Measured in rcssserver3d 0.7.3 with
 * scripts/phalanx bench ball-decay: k = 1.062 /s for every start speed (the drag is linear); a ball set moving
 * without spin first slides and rolls on at 0.63 of its speed (agent/README.md).
 */
public final class BallRoll {
    private BallRoll() {}

    /**
     * A crossing of the line x = 0 (body frame: the keeper's Y axis).
     *
     * @param seconds from now until the ball reaches the line
     * @param lateral where it crosses, metres along +y (left) of the keeper
     */
    public record Crossing(double seconds, double lateral) {}

    /**
     * The crossing of a ball at {@code position} moving at {@code velocity} (both body frame, m and
     * m/s) under decay rate {@code k} (1/s; 0 = no friction), or null when it moves away, stands,
     * lies behind the line or stops before it.
     */
    public static Crossing crossing(Vector2 position, Vector2 velocity, double k) {
        if (position == null || velocity == null || !position.isFinite() || !velocity.isFinite()) return null;
        if (!(k >= 0) || !Double.isFinite(k)) return null;
        double x = position.x(), vx = velocity.x();
        if (x <= 0 || vx >= 0) return null;
        double speedIn = -vx;
        double t;
        if (k == 0) {
            t = x / speedIn;
        } else {
            double f = 1 - k * x / speedIn;   // e^(-k t) at the crossing
            if (f <= 0) return null;          // it stops first: the reach v/k is not more than x
            t = -Math.log(f) / k;
        }
        // Friction slows the ball along its path, it does not bend it: the crossing is the straight line's.
        return new Crossing(t, position.y() + velocity.y() * x / speedIn);
    }

    /** Distance a ball starting at speed v0 covers in t seconds under decay rate k. */
    public static double distance(double v0, double k, double t) {
        return k == 0 ? v0 * t : v0 * (1 - Math.exp(-k * t)) / k;
    }
}

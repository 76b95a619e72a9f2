package phalanx.bench.motion;

/**
 * The speed a kick gives the ball, from the monitor's ball positions: the highest horizontal speed and
 * the highest upward speed between two pictures of different time. Distance alone mixes launch speed
 * with loft and the ground's slide (a ball that starts sliding keeps 0.63 of its speed, agent/README.md
 * "ball decay"), so the bench prints both (motion/README.md "Kicks and dives").
 */
final class BallLaunch {
    private double t = Double.NaN, x, y, z;
    private double speed, up;

    /** One monitor picture: its time (s) and the ball centre (m). A picture of the same time is ignored. */
    void add(double time, double bx, double by, double bz) {
        if (!Double.isNaN(t)) {
            if (time <= t) return;
            double dt = time - t;
            speed = Math.max(speed, Math.hypot(bx - x, by - y) / dt);
            up = Math.max(up, (bz - z) / dt);
        }
        t = time; x = bx; y = by; z = bz;
    }

    /** Highest horizontal ball speed seen, m/s. */
    double speed() { return speed; }

    /** Highest upward ball speed seen, m/s (0 for a ball that never rose). */
    double up() { return up; }
}

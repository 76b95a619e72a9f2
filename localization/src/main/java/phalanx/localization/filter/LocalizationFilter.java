package phalanx.localization.filter;

import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * Thesis 4.4.3, Algorithm 1: a FIFO queue of the MaxSize most recent agreeing estimates; the
 * belief is their average. An estimate that disagrees with the average is dropped and removes the
 * oldest entry, so a persistent new location empties the queue and starts a new belief.
 * Used for the self pose (with orientation) and for the ball (position only: angle check off).
 * Beyond the thesis: {@link #shift} moves the queued estimates by the robot's own motion
 * (odometry), so walking does not make the average lag. Fixed arrays, no allocation per update.
 */
public final class LocalizationFilter {
    private final int maxSize;
    private final double agreeMetres, agreeDeg;
    private final boolean withAngle;
    private final double[] xs, ys, ts;
    private int head, size;
    private int accepted, rejected;

    /**
     * @param agreeDeg the orientation agreement threshold; NaN for position-only estimates (the ball)
     */
    public LocalizationFilter(int maxSize, double agreeMetres, double agreeDeg) {
        if (maxSize < 1) throw new IllegalArgumentException("maxSize must be at least 1");
        this.maxSize = maxSize;
        this.agreeMetres = agreeMetres;
        this.agreeDeg = agreeDeg;
        this.withAngle = !Double.isNaN(agreeDeg);
        xs = new double[maxSize];
        ys = new double[maxSize];
        ts = new double[maxSize];
    }

    /** Algorithm 1 with a pose estimate; returns true when it was accepted into the queue. */
    public boolean add(Pose2 estimate) {
        return add(estimate.x(), estimate.y(), estimate.thetaDeg());
    }

    /** Algorithm 1 with a position estimate (the ball). */
    public boolean add(Vector2 estimate) {
        return add(estimate.x(), estimate.y(), 0);
    }

    private boolean add(double x, double y, double t) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(t)) return false;
        if (size > 0 && !agrees(x, y, t)) {
            removeOldest();                     // Algorithm 1, line 8
            rejected++;
            return false;
        }
        if (size == maxSize) removeOldest();    // lines 10-11
        int i = (head + size) % maxSize;        // line 13
        xs[i] = x;
        ys[i] = y;
        ts[i] = t;
        size++;
        accepted++;
        return true;
    }

    private boolean agrees(double x, double y, double t) {
        double mx = meanX(), my = meanY();
        if (Math.hypot(x - mx, y - my) > agreeMetres) return false;
        return !withAngle || Math.abs(Angles.difference(t, meanTheta())) <= agreeDeg;
    }

    private void removeOldest() {
        if (size == 0) return;
        head = (head + 1) % maxSize;
        size--;
    }

    /**
     * Moves every queued pose by a motion of the body: forward/left metres and a turn in degrees,
     * expressed in the body frame of each estimate (odometry of the walk).
     */
    public void shift(double forward, double left, double turnDeg) {
        for (int k = 0; k < size; k++) {
            int i = (head + k) % maxSize;
            double r = Math.toRadians(ts[i]), c = Math.cos(r), s = Math.sin(r);
            xs[i] += c * forward - s * left;
            ys[i] += s * forward + c * left;
            ts[i] = Angles.normalize(ts[i] + turnDeg);
        }
    }

    /** Moves every queued position by a displacement (a ball observed to roll). */
    public void translate(double dx, double dy) {
        for (int k = 0; k < size; k++) {
            int i = (head + k) % maxSize;
            xs[i] += dx;
            ys[i] += dy;
        }
    }

    public boolean isEmpty() { return size == 0; }
    public int size() { return size; }
    public int maxSize() { return maxSize; }
    public int accepted() { return accepted; }
    public int rejected() { return rejected; }
    public void clear() { size = 0; }

    /** The average of the queue (Algorithm 1, line 15), or null when it is empty. */
    public Pose2 pose() {
        return size == 0 ? null : new Pose2(meanX(), meanY(), withAngle ? meanTheta() : 0);
    }

    public Vector2 position() {
        return size == 0 ? null : new Vector2(meanX(), meanY());
    }

    private double meanX() {
        double s = 0;
        for (int k = 0; k < size; k++) s += xs[(head + k) % maxSize];
        return s / size;
    }

    private double meanY() {
        double s = 0;
        for (int k = 0; k < size; k++) s += ys[(head + k) % maxSize];
        return s / size;
    }

    private double meanTheta() {
        double c = 0, s = 0;
        for (int k = 0; k < size; k++) {
            double r = Math.toRadians(ts[(head + k) % maxSize]);
            c += Math.cos(r);
            s += Math.sin(r);
        }
        return Math.toDegrees(Math.atan2(s, c));
    }
}

package phalanx.localization.tracking;

import phalanx.model.field.Vector2;

/**
 * Thesis 4.6, Track Moving Object: the direction and speed of a moving object from two sets of
 * {@code setSize} consecutive observations, the second set {@code delay} observations after the
 * first; the difference of the two sets' mean positions over the difference of their mean times.
 * Ring buffer of fixed arrays; an observation older than the newest by more than {@code maxGap}
 * seconds (the object left the view) restarts the history.
 */
public final class MovingObjectTracker {
    private final int setSize, delay, capacity;
    private final double maxGap;
    private final double[] xs, ys, ts;
    private int count, next;

    public MovingObjectTracker(int setSize, int delay, double maxGapSeconds) {
        if (setSize < 1 || delay < 1) throw new IllegalArgumentException("setSize and delay must be at least 1");
        this.setSize = setSize;
        this.delay = delay;
        this.capacity = setSize + delay;
        this.maxGap = maxGapSeconds;
        xs = new double[capacity];
        ys = new double[capacity];
        ts = new double[capacity];
    }

    /** Adds one observation (position in any fixed frame, time in seconds); bad values are ignored. */
    public void observe(Vector2 p, double time) {
        if (p == null || !p.isFinite() || !Double.isFinite(time)) return;
        if (count > 0) {
            double last = ts[(next - 1 + capacity) % capacity];
            if (time <= last) return;
            if (time - last > maxGap) count = 0;
        }
        xs[next] = p.x();
        ys[next] = p.y();
        ts[next] = time;
        next = (next + 1) % capacity;
        if (count < capacity) count++;
    }

    /** True once both sets are full. */
    public boolean ready() { return count >= capacity; }

    /** Velocity in metres per second (the frame of the observations), or null until {@link #ready}. */
    public Vector2 velocity() {
        if (!ready()) return null;
        double ox = 0, oy = 0, ot = 0, nx = 0, ny = 0, nt = 0;
        for (int k = 0; k < setSize; k++) {
            int old = (next + k) % capacity;                  // oldest set
            int recent = (next + delay + k) % capacity;       // the set delay observations later
            ox += xs[old]; oy += ys[old]; ot += ts[old];
            nx += xs[recent]; ny += ys[recent]; nt += ts[recent];
        }
        double dt = (nt - ot) / setSize;
        if (!(dt > 0)) return null;
        return new Vector2((nx - ox) / setSize / dt, (ny - oy) / setSize / dt);
    }

    /**
     * How long before {@code now} the {@link #velocity} applies, seconds: from the midpoint of the two sets' mean
     * times (the velocity is their mean over that span). NaN until {@link #ready}.
     */
    public double age(double now) {
        if (!ready()) return Double.NaN;
        double ot = 0, nt = 0;
        for (int k = 0; k < setSize; k++) {
            ot += ts[(next + k) % capacity];
            nt += ts[(next + delay + k) % capacity];
        }
        return now - (ot + nt) / (2 * setSize);
    }

    public void clear() { count = 0; }
}

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
 * <p>
 * Also beyond the thesis, and off unless a relocation count is given (the self filter turns it on, the
 * ball's too since session 19): <b>relocation</b>. When {@code relocateFrames} refused estimates in a row
 * are each farther than {@code relocateMetres} (or {@code relocateDeg}) from the average and each within
 * {@code spreadMetres} ({@code spreadDeg}) of the one before, the queue is replaced by them: the robot
 * was moved (beam, trainer or referee). Algorithm 1 alone needs MaxSize refusals before its queue is
 * empty and a new belief can start (issue 19). Accepted or near estimates reset the count. A single far
 * estimate flagged consistent ({@link #add(Pose2, boolean)}: every landmark of its frame fits it) relocates at once.
 */
public final class LocalizationFilter {
    private final int maxSize;
    private final double agreeMetres, agreeDeg;
    private final boolean withAngle;
    private final double[] xs, ys, ts;
    /** Per entry: the distance (m) and the turn (deg, absolute) {@link #shift} has moved it by since it was taken. */
    private final double[] moved, turned;
    /** Motion weighting (off while odometryShare is NaN): see {@link #weighByMotion}. */
    private double sigmaMetres = Double.NaN, sigmaDeg = Double.NaN, odometryShare = Double.NaN;
    private int head, size;
    private int accepted, rejected, starts, relocations;
    /** Relocation (off when relocateFrames is 0) and the refused estimates counted towards it, oldest first. */
    private final int relocateFrames;
    private final double relocateMetres, relocateDeg, spreadMetres, spreadDeg;
    private final double[] px, py, pt;
    private int pending;

    /**
     * @param agreeDeg the orientation agreement threshold; NaN for position-only estimates (the ball)
     */
    public LocalizationFilter(int maxSize, double agreeMetres, double agreeDeg) {
        this(maxSize, agreeMetres, agreeDeg, 0, Double.NaN, Double.NaN, Double.NaN, Double.NaN);
    }

    /**
     * Algorithm 1 with relocation (class comment): after {@code relocateFrames} refused estimates in a row,
     * far from the average and close to each other, the queue restarts from them. 0 frames: the thesis's filter.
     * The angle thresholds are ignored for position-only estimates (agreeDeg NaN).
     */
    public LocalizationFilter(int maxSize, double agreeMetres, double agreeDeg, int relocateFrames,
                              double relocateMetres, double relocateDeg, double spreadMetres, double spreadDeg) {
        if (maxSize < 1) throw new IllegalArgumentException("maxSize must be at least 1");
        if (relocateFrames < 0) throw new IllegalArgumentException("relocateFrames must be 0 (off) or more");
        this.relocateFrames = Math.min(relocateFrames, maxSize);
        this.relocateMetres = relocateMetres;
        this.relocateDeg = relocateDeg;
        this.spreadMetres = spreadMetres;
        this.spreadDeg = spreadDeg;
        int n = Math.max(1, this.relocateFrames);
        px = new double[n];
        py = new double[n];
        pt = new double[n];
        this.maxSize = maxSize;
        this.agreeMetres = agreeMetres;
        this.agreeDeg = agreeDeg;
        this.withAngle = !Double.isNaN(agreeDeg);
        xs = new double[maxSize];
        ys = new double[maxSize];
        ts = new double[maxSize];
        moved = new double[maxSize];
        turned = new double[maxSize];
    }

    /**
     * Beyond the thesis (issue 19): the average weighs each estimate by how far {@link #shift} has moved it. The
     * walk's odometry is off by about a tenth of the motion, so an estimate moved by it is that much less sure:
     * position weight 1 / (sigmaMetres² + (share · metres moved)²), heading weight 1 / (sigmaDeg² + (share · degrees
     * turned)²). Without motion every weight is the same and the average is Algorithm 1's. Returns this.
     */
    public LocalizationFilter weighByMotion(double sigmaMetres, double sigmaDeg, double odometryShare) {
        if (!(sigmaMetres > 0) || !(sigmaDeg > 0) || !(odometryShare >= 0))
            throw new IllegalArgumentException("motion weighting needs positive sigmas and a share >= 0");
        this.sigmaMetres = sigmaMetres;
        this.sigmaDeg = sigmaDeg;
        this.odometryShare = odometryShare;
        return this;
    }

    private boolean weighted() { return !Double.isNaN(odometryShare); }

    private double positionWeight(int i) {
        if (!weighted()) return 1;
        double e = odometryShare * moved[i];
        return 1 / (sigmaMetres * sigmaMetres + e * e);
    }

    private double headingWeight(int i) {
        if (!weighted()) return 1;
        double e = odometryShare * turned[i];
        return 1 / (sigmaDeg * sigmaDeg + e * e);
    }

    /** Algorithm 1 with a pose estimate; returns true when it was accepted into the queue. */
    public boolean add(Pose2 estimate) {
        return add(estimate.x(), estimate.y(), estimate.thetaDeg(), false);
    }

    /**
     * The same, where {@code consistent} says the estimate's own evidence agrees with it (the self filter: every
     * landmark of the frame fits the fix). With relocation on, a consistent estimate far from the average
     * replaces the queue at once instead of being refused (issue 19).
     */
    public boolean add(Pose2 estimate, boolean consistent) {
        return add(estimate.x(), estimate.y(), estimate.thetaDeg(), consistent);
    }

    /** Algorithm 1 with a position estimate (the ball). */
    public boolean add(Vector2 estimate) {
        return add(estimate.x(), estimate.y(), 0, false);
    }

    private boolean add(double x, double y, double t, boolean consistent) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(t)) return false;
        if (size > 0 && !agrees(x, y, t)) {
            boolean far = relocateFrames > 0 && far(x, y, t);
            removeOldest();                     // Algorithm 1, line 8
            rejected++;
            if (!far) {
                pending = 0;
                return false;
            }
            // Relocation (not in the thesis): count this refusal if it agrees with the one before; a
            // consistent estimate is enough on its own.
            if (consistent || (pending > 0 && !nearLastPending(x, y, t))) pending = 0;
            px[pending] = x;
            py[pending] = y;
            pt[pending] = t;
            if (++pending < relocateFrames && !consistent) return false;
            head = 0;
            size = 0;
            for (int k = 0; k < pending; k++) {
                xs[k] = px[k];
                ys[k] = py[k];
                ts[k] = pt[k];
                moved[k] = turned[k] = 0;   // (the pending estimates' own motion is not kept: they start afresh)
            }
            size = pending;
            pending = 0;
            starts++;
            relocations++;
            accepted++;
            return true;
        }
        pending = 0;
        if (size == 0) starts++;                // a new belief: the first, or after refusals emptied the queue
        if (size == maxSize) removeOldest();    // lines 10-11
        int i = (head + size) % maxSize;        // line 13
        xs[i] = x;
        ys[i] = y;
        ts[i] = t;
        moved[i] = turned[i] = 0;
        size++;
        accepted++;
        return true;
    }

    private boolean agrees(double x, double y, double t) {
        double mx = meanX(), my = meanY();
        if (Math.hypot(x - mx, y - my) > agreeMetres) return false;
        return !withAngle || Math.abs(Angles.difference(t, meanTheta())) <= agreeDeg;
    }

    /** Farther than the relocation thresholds from the average (the angle only with orientation). */
    private boolean far(double x, double y, double t) {
        if (Math.hypot(x - meanX(), y - meanY()) > relocateMetres) return true;
        return withAngle && Math.abs(Angles.difference(t, meanTheta())) > relocateDeg;
    }

    private boolean nearLastPending(double x, double y, double t) {
        int j = pending - 1;
        if (Math.hypot(x - px[j], y - py[j]) > spreadMetres) return false;
        return !withAngle || Math.abs(Angles.difference(t, pt[j])) <= spreadDeg;
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
            moved[i] += Math.hypot(forward, left);
            turned[i] += Math.abs(turnDeg);
        }
        for (int k = 0; k < pending; k++) {
            double r = Math.toRadians(pt[k]), c = Math.cos(r), s = Math.sin(r);
            px[k] += c * forward - s * left;
            py[k] += s * forward + c * left;
            pt[k] = Angles.normalize(pt[k] + turnDeg);
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
    /** Times a belief began: the first estimate, one after refusals emptied the queue, a relocation. */
    public int starts() { return starts; }
    /** Times the queue was replaced by relocation (a subset of {@link #starts}). */
    public int relocations() { return relocations; }
    /** Refused estimates counted towards a relocation so far (0 when none is under way). */
    public int pending() { return pending; }
    public void clear() { size = 0; pending = 0; }

    /** The average of the queue (Algorithm 1, line 15), or null when it is empty. */
    public Pose2 pose() {
        return size == 0 ? null : new Pose2(meanX(), meanY(), withAngle ? meanTheta() : 0);
    }

    public Vector2 position() {
        return size == 0 ? null : new Vector2(meanX(), meanY());
    }

    private double meanX() { return weightedMean(xs); }

    private double meanY() { return weightedMean(ys); }

    /** The queue's mean of one coordinate, each entry weighted by positionWeight. */
    private double weightedMean(double[] values) {
        double s = 0, w = 0;
        for (int k = 0; k < size; k++) {
            int i = (head + k) % maxSize;
            double wi = positionWeight(i);
            s += wi * values[i];
            w += wi;
        }
        return s / w;
    }

    private double meanTheta() {
        double c = 0, s = 0;
        for (int k = 0; k < size; k++) {
            int i = (head + k) % maxSize;
            double r = Math.toRadians(ts[i]), w = headingWeight(i);
            c += w * Math.cos(r);
            s += w * Math.sin(r);
        }
        return Math.toDegrees(Math.atan2(s, c));
    }
}

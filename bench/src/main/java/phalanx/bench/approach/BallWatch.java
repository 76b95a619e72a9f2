package phalanx.bench.approach;

/**
 * One approach trial read off the monitor's pictures of the ball (ground truth): the ball is set still at
 * {@code start}; the trial ends {@code settleS} (a kick: {@link #SETTLE_S}) after the ball was last seen moving once it has been
 * touched (moved more than {@link #TOUCH_M} from where it lay), or when nothing touched it within
 * {@code noTouchS}, or {@code afterTouchS} after the first touch (a dribble goes on and on).
 */
final class BallWatch {
    /** A still ball moved this far is touched: more than the pictures' jitter, less than any real push. */
    static final double TOUCH_M = 0.05;
    /** Moving: more than this between two pictures (0.04 s apart: 0.25 m/s). */
    static final double MOVING_M = 0.01;
    /** Still this long after the touch: the kick is over. */
    static final double SETTLE_S = 1.0;

    enum End { RUNNING, SETTLED, NO_TOUCH, TIME_UP }

    /**
     * The attack trial's settle time: none. A dribble leaves the ball still between its pushes, and after a short kick
     * the player walks to the ball again (4 s ended 17 of 20 attacks of the quick shot as 'stopped' while it was still
     * on its way); the attack ends at a goal, out, or the touch limit.
     */
    static final double ATTACK_SETTLE_S = Double.POSITIVE_INFINITY;

    private final double x0, y0, t0, noTouchS, afterTouchS, settleS;
    private double touchedAt = Double.NaN, lastMoving = Double.NaN, px, py, x, y;

    BallWatch(double t0, double x0, double y0, double noTouchS, double afterTouchS) {
        this(t0, x0, y0, noTouchS, afterTouchS, SETTLE_S);
    }

    BallWatch(double t0, double x0, double y0, double noTouchS, double afterTouchS, double settleS) {
        this.settleS = settleS;
        this.t0 = t0;
        this.x0 = x0;
        this.y0 = y0;
        this.noTouchS = noTouchS;
        this.afterTouchS = afterTouchS;
        this.px = this.x = x0;
        this.py = this.y = y0;
    }

    /** One picture at game time {@code t}; returns whether and how the trial is over. */
    End see(double t, double bx, double by) {
        px = x;
        py = y;
        x = bx;
        y = by;
        if (Double.isNaN(touchedAt)) {
            if (Math.hypot(x - x0, y - y0) > TOUCH_M) touchedAt = lastMoving = t;
            else return t - t0 > noTouchS ? End.NO_TOUCH : End.RUNNING;
        }
        if (Math.hypot(x - px, y - py) > MOVING_M) lastMoving = t;
        if (t - lastMoving >= settleS) return End.SETTLED;
        return t - touchedAt > afterTouchS ? End.TIME_UP : End.RUNNING;
    }

    /** Game seconds from the ball's placing to its first touch; NaN when untouched. */
    double timeToTouch() { return touchedAt - t0; }

    /** How far the ball is from where it was set (m). */
    double travel() { return Math.hypot(x - x0, y - y0); }

    /** Direction of the ball's travel, degrees (field frame); NaN when it did not move. */
    double directionDeg() { return travel() < TOUCH_M ? Double.NaN : Math.toDegrees(Math.atan2(y - y0, x - x0)); }

    double x() { return x; }
    double y() { return y; }
}

package phalanx.agent.action;

import phalanx.agent.decide.Situation;

/**
 * Follows one play of a one-shot motion (kick, dive, stand up) through the motion controller's
 * status, without knowing file names: the motion begins when something other than what was
 * playing at the request starts playing, and it has ended when the controller counts a
 * completion after that (or it stopped playing). A motion that never shows up ends after a
 * timeout, so a missing file cannot hang an action.
 *
 * <p>The move is requested only until the motion shows as playing ({@link #requesting}): the
 * motion controller restarts a one-shot motion that is still requested when it ends, and a kick
 * without a finalize phase would then play twice. Requesting nothing lets it play to its end.
 */
public final class OneShot {
    private final double timeout;
    private boolean active;
    private boolean began;
    private String before;
    private String mine;
    private long completionsAtBegin;
    private double since;

    public OneShot(double timeoutSeconds) { this.timeout = timeoutSeconds; }

    /** Starts following a new play from this cycle. */
    public void start(Situation s) {
        active = true;
        began = false;
        before = s.motion() == null ? null : s.motion().playing();
        mine = null;
        since = s.now();
    }

    public boolean active() { return active; }

    /** True while the move must still be requested (the motion has not begun yet). */
    public boolean requesting() { return active && !began; }

    /** Updates with this cycle's status; true once the play has ended (then inactive). */
    public boolean finished(Situation s) {
        if (!active) return true;
        Situation.MotionStatus m = s.motion() == null ? Situation.MotionStatus.IDLE : s.motion();
        if (!began) {
            // The motion that played at the request may be finishing first (a walk's finalize).
            if (m.playing() != null && (before == null || !m.playing().equals(before))) {
                began = true;
                mine = m.playing();
                completionsAtBegin = m.completions();
            } else if (m.playing() == null) {
                before = null;
            }
        } else if (m.completions() > completionsAtBegin || m.playing() == null || !m.playing().equals(mine)) {
            active = false;
            return true;
        }
        if (!(s.now() - since <= timeout)) {   // also ends on a NaN clock
            active = false;
            return true;
        }
        return false;
    }
}

package phalanx.agent.mj;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * The double-touch rule as one player keeps it (soccer_referee.py {@code _check_fouls}, {@code agent_na_touch_ball} and
 * {@code _check_contact_triggers}, rcsssmj 0.2.1): the touch that ends a kick-off, kick-in, corner, free kick or direct
 * free kick (the referee then gives PlayOn) bars its player from the ball until someone else has touched it; touching it
 * again more than 1 s after that first touch began gives the other side a free kick. A goal kick bars nobody (its PlayOn
 * comes when the ball leaves the goalie area), nor a set piece that ran out its 15 s untouched. Any new referee decision
 * (a set piece, a goal, game over) lifts the bar.
 * <p>
 * We cannot sense touches, so: our set piece turning into PlayOn before its 15 s, while this player kicks or stands within
 * {@link #TOUCHED_M} of the ball, is its touch; and the bar is lifted once another player is seen with a foot within
 * {@link #OTHER_AT_BALL_M} of the ball, or a team-mate reports itself where it kicks from
 * ({@link MjTeamTalk#mateAtBall}). Whatever touch ended the set piece (the kick, or a push while walking up to kick) is
 * the taker's one touch: a kick still waiting is dropped (MjRuntime), and a barred player keeps off the ball and reports
 * itself unable to play it (MjTeamTalk), so that the coordinator gives On Ball to another.
 */
final class MjTouchRule {
    private static final Logger LOG = Logger.getLogger(MjTouchRule.class.getName());
    /** Ours: torso to ball when a set piece of ours turns into PlayOn; the kick's stance is 0.34 m (T1KickConfig), a push on the approach nearer. */
    static final double TOUCHED_M = 0.7;
    /** Ours: a seen foot this near the ball's centre (radius 0.11 m) counts as another player's touch. */
    static final double OTHER_AT_BALL_M = 0.3;
    /** The set pieces' 15 s (soccer_rules.py); a little less, so that a PlayOn at the very end counts as the timeout. */
    static final double SET_PIECE_S = 14.9;

    private boolean barred;
    private long bars;

    /**
     * One cycle, after the world took the perception. {@code kicking}: our kick is playing or waiting to start;
     * {@code otherAtBall}: another player has just been at the ball (seen, or a team-mate's report).
     */
    void update(MjWorld w, boolean kicking, boolean otherAtBall) {
        String now = w.playMode();
        if (!now.equals(mode)) {
            String was = mode;
            if (now.equals("PlayOn") && endsByTouch(was) && w.ours(was) && w.time() - modeSince < SET_PIECE_S && near(w, kicking)) {
                barred = true;
                bars++;
                LOG.info(String.format(Locale.ROOT, "double touch: %s ended by our touch at %.2f s, off the ball until another player has played it",
                        was, w.time()));
            } else if (!now.equals("PlayOn") && barred) {
                barred = false;
                LOG.info(String.format(Locale.ROOT, "double touch: %s at %.2f s, free to play the ball again", now, w.time()));
            }
            mode = now;
            modeSince = w.time();
        } else if (barred && otherAtBall) {
            barred = false;
            LOG.info(String.format(Locale.ROOT, "double touch: another player at the ball at %.2f s, free to play it again", w.time()));
        }
    }

    /** The play mode as this rule last saw it, and since when (game time). */
    private String mode = "";
    private double modeSince = Double.NEGATIVE_INFINITY;

    private static boolean near(MjWorld w, boolean kicking) {
        return kicking || w.self() != null && w.ball() != null && w.self().position().distanceTo(w.ball()) < TOUCHED_M;
    }

    /** The set pieces whose first touch gives PlayOn and bars the toucher (soccer_referee.py {@code _check_contact_triggers}). */
    static boolean endsByTouch(String mode) {
        String m = mode.toLowerCase(Locale.ROOT);
        return m.startsWith("kickoff_") || m.startsWith("kickin_") || m.startsWith("corner_kick_") || m.startsWith("free_kick_")
                || m.startsWith("direct_free_kick_");
    }

    /** This player may not touch the ball now. */
    boolean barred() { return barred; }

    /** How often this player was barred (its log's last line). */
    long bars() { return bars; }
}

package phalanx.bench.motion;

import phalanx.comm.perception.PlayMode;

import java.util.Locale;

/**
 * Why a motion-bench trial measured nothing, decided on what the monitor's scene graph and our player's
 * own messages showed (issue 22: on a server that did not do what the bench asked, every kick printed
 * "0.00 m, direction error NaN" and the summary looked like a result). Each check returns null when the
 * trial measured something, else the reason, one line, printed with the trial and counted in the summary.
 * A trial with a reason adds no figure; the bench exits with status 3 when a figure it was asked for got
 * no measured trial at all.
 */
final class TrialCheck {
    private TrialCheck() { }

    /** A trainer move puts the torso within a few cm of its target; a robot that stumbles after it stays near. */
    static final double MOVE_TOLERANCE = 0.25;
    /** The bench's game time after {@code (time 0)} and one second standing: more means the reset never arrived. */
    static final double RESET_GAME_TIME = 2.0;
    /** More than this ahead of our player's messages, the monitor shows a server that does not wait for our player. */
    static final double RUNS_AHEAD = 0.5;
    /** The ball lies within 1 cm of its spot once the monitor shows the trainer's placement. */
    static final double BALL_TOLERANCE = 0.02;
    /** Anything that touches the ball moves it more than this; a ball that moved less never moved. */
    static final double BALL_STILL = 0.01;
    /** Nothing of the robot moved more than this in a whole motion: the robot in the picture is not ours. */
    static final double BODY_STILL = 0.01;
    /**
     * A body part's centre closer than this to the ball's centre touches it (a foot is 16 cm long, the ball's
     * radius 4.2 cm); the wording of "never reached" only.
     */
    static final double REACH = 0.13;

    /**
     * After a trainer move and a second standing.
     *
     * @param offTarget   the torso's distance from the move's target (m), NaN when the monitor's scene has no
     *                    player 1 of team Left
     * @param gameTime    the game time in our player's last message (s)
     * @param playMode    the play mode in it
     * @param pictures    monitor pictures that arrived during that second
     * @param ahead       the latest picture's game time minus our player's (s): a picture of the same server is
     *                    at most a cycle ahead, since the server waits for our player in agent-sync mode
     */
    static String placement(double offTarget, double gameTime, PlayMode playMode, int pictures, double ahead) {
        if (ahead > RUNS_AHEAD) {
            return String.format(Locale.ROOT, "the monitor's picture is %.2f s of game time ahead of our player: the server does not wait for it"
                    + " (not in agent-sync mode?)", ahead);
        }
        if (pictures == 0) return "no monitor picture came in the second after the trainer move (the monitor's stream stopped)";
        if (Double.isNaN(offTarget)) return "no player 1 of team Left in the monitor's scene (the monitor port is another server's?)";
        if (!(gameTime <= RESET_GAME_TIME) || playMode != PlayMode.PLAY_ON) {
            return String.format(Locale.ROOT, "the trainer's (time 0) (playMode PlayOn) did not reach our player: its game time %.2f s, play mode %s"
                    + " (are the agent and monitor ports one server's?)", gameTime, playMode == null ? "none" : playMode.wireName());
        }
        if (offTarget > MOVE_TOLERANCE) {
            return String.format(Locale.ROOT, "the trainer move had no effect: the robot stands %.2f m from where it was moved", offTarget);
        }
        return null;
    }

    /**
     * One kick, from the ball's placement until it stopped.
     *
     * @param ballOffSpot the ball's distance from where the trainer put it when the kick started (m), NaN when
     *                    the scene has no ball
     * @param pictures    monitor pictures during the kick
     * @param bodyTravel  the most any of the robot's body parts moved from where it was at the kick's start (m)
     * @param closest     the closest any body part's centre came to the ball's centre (m)
     * @param ballTravel  the most the ball got from where it lay at the start (m)
     */
    static String kick(double ballOffSpot, int pictures, double bodyTravel, double closest, double ballTravel) {
        if (pictures == 0) return "no monitor picture came during the kick (the monitor's stream stopped)";
        if (Double.isNaN(ballOffSpot)) return "no ball in the monitor's scene";
        if (ballOffSpot > BALL_TOLERANCE) {
            return String.format(Locale.ROOT, "the ball was not on its spot when the kick started: it lay %.2f m away (the trainer's (ball ...) had no effect?)", ballOffSpot);
        }
        if (!(bodyTravel >= BODY_STILL)) return "the robot in the monitor's scene never moved while our player kicked (it is not our player?)";
        if (!(ballTravel >= BALL_STILL)) {
            return closest > REACH
                    ? String.format(Locale.ROOT, "the ball never moved: the robot never reached it (its nearest part %.2f m from the ball's centre)", closest)
                    : String.format(Locale.ROOT, "the ball never moved, though the robot's nearest part came %.2f m from its centre", closest);
        }
        return null;
    }

    /**
     * A walk or turn: the robot must have moved at all, else the figure (0 m/s, 0 °/s) is no result.
     *
     * @param pictures   monitor pictures during the trial
     * @param bodyTravel how far the torso got from its start, or turned (m or rad; anything above noise)
     */
    static String motion(int pictures, double bodyTravel) {
        if (pictures == 0) return "no monitor picture came during the trial (the monitor's stream stopped)";
        if (!(bodyTravel >= BODY_STILL)) return "the robot in the monitor's scene never moved (it is not our player?)";
        return null;
    }
}

package phalanx.agent.mj;

import phalanx.agent.goalkeeper.Goalkeeper;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * The T1 goalkeeper's states, thesis 5.13 on rcssservermj (MjBehaviour carries them out):
 * <pre>
 * GUARD   on the spot's line (spotOffset in front of our goal line), between the goal's centre and the ball, at most
 *         maxShift from the middle (the SimSpark keeper's geometry, {@link Goalkeeper#guardPoint}); back there after Libero
 * LIBERO  the ball inside our penalty area, fresh, and nearer to the keeper than to any opponent seen, by
 *         opponentMargin -> to the ball and kick it away (On Ball's approach and kick)     -> GUARD when it is out of the
 *         area by exitMargin, an opponent is nearer, the ball is lost, or we may not play it
 * </pre>
 * The thesis's Libero waits for a still ball in the goal area with nobody near; ours takes the task's rule (the penalty
 * area, nearer than every opponent), since on this server the keeper may handle the ball there too and 9 x 16.5 m is where
 * a T1 at 0.5 m/s can get to a ball first. No DIVING: the T1 has no dive motion (motions/t1 holds its get-ups only), so a
 * shot is met by standing on its line. While in Libero the coordinator plans in Support mode (5.2: the goalkeeper has
 * the ball, no field player goes On Ball), as on SimSpark.
 */
final class MjKeeper {
    private static final Logger LOG = Logger.getLogger(MjKeeper.class.getName());

    enum State { GUARD, LIBERO }

    /**
     * Ours (no thesis figure for the T1): the spot 1 m in front of the goal line (the T1 is 1.2 m tall, the goal 1 m deep)
     * and at most 1.2 m to either side of the middle (the goal's half width is 1.83 m, the T1's shoulders ~0.2 m to a
     * side); Libero for a ball seen within ballFreshS, nearer to the keeper than to every opponent by opponentMargin;
     * kept while the ball was seen within ballKeepS (at its feet, where it stands to kick, the camera's 60 degrees below
     * the horizon miss it: in MjKeeperServerTest it lost the ball 0.5 m in front of it and turned back), until the ball
     * is exitMargin out of the area.
     */
    record Config(double spotOffset, double maxShift, double ballFreshS, double ballKeepS, double opponentMargin, double exitMargin) {
        static final Config DEFAULT = new Config(1.0, 1.2, 1.0, 4.0, 0.5, 1.0);
    }

    private final FieldSpec field;
    private final Config c;
    private State state = State.GUARD;

    MjKeeper(MjField field, Config c) {
        this.field = field.spec();
        this.c = c;
    }

    State state() { return state; }

    /** The state for this cycle. {@code mayPlayBall}: the play mode and the double-touch rule let us touch the ball. */
    State update(MjWorld w, boolean mayPlayBall) {
        State next = next(w, mayPlayBall);
        if (next != state) LOG.info(String.format(Locale.ROOT, "keeper %s at %.2f s self=%s ball=%s", next, w.time(), w.self(), w.ball()));
        state = next;
        return state;
    }

    private State next(MjWorld w, boolean mayPlayBall) {
        Vector2 ball = w.ball();
        boolean libero = state == State.LIBERO;
        if (!mayPlayBall || ball == null || w.self() == null || w.ballAge() > (libero ? c.ballKeepS() : c.ballFreshS())) return State.GUARD;
        double mine = w.self().position().distanceTo(ball), theirs = w.opponentDistance(ball);
        if (libero) {
            boolean keep = Goalkeeper.inGoalArea(field, ball, c.exitMargin()) && mine < theirs;
            return keep ? State.LIBERO : State.GUARD;
        }
        return Goalkeeper.inGoalArea(field, ball, 0) && mine + c.opponentMargin() < theirs ? State.LIBERO : State.GUARD;
    }

    /** Guard's place: on the spot's line between our goal's centre and the ball (no ball: the middle). */
    Vector2 guardPoint(Vector2 ball) {
        double goalX = -field.halfLength();
        return ball == null ? new Vector2(goalX + c.spotOffset(), 0) : Goalkeeper.guardPoint(goalX, c.spotOffset(), c.maxShift(), ball);
    }

    /** True while it clears the ball: the coordination's Support mode (5.2, 5.13). */
    boolean hasBall() { return state == State.LIBERO; }
}

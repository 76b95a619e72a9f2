package phalanx.coordination;

import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;

/** The three coordination modes of thesis 5.2. */
public enum Mode {
    /** Normal play: goalkeeper, inactive, active and support subsets. */
    ACTIVE,
    /** Every field player joins the support subset: our goalkeeper has the ball, or only the opponents may kick it. */
    SUPPORT,
    /** Every field player joins the inactive subset: waiting for a kick-off. */
    WAIT;

    /**
     * The mode for a play mode (5.2).
     *
     * @param ourSide           the side our team plays on
     * @param goalkeeperHasBall the goalkeeper is clearing the ball (its Libero state, 5.13)
     */
    public static Mode of(PlayMode playMode, Side ourSide, boolean goalkeeperHasBall) {
        if (playMode == null || ourSide == null)
            throw new IllegalArgumentException("play mode and side are needed, got " + playMode + ", " + ourSide);
        switch (playMode) {
            case BEFORE_KICK_OFF, GOAL_LEFT, GOAL_RIGHT, GAME_OVER: return WAIT;
            default: break;
        }
        if (goalkeeperHasBall) return SUPPORT;
        Side kicker = kicker(playMode);
        return kicker == null || kicker == ourSide ? ACTIVE : SUPPORT;
    }

    /**
     * The side allowed to play the ball, or null when both are (play on, or a mode this client does
     * not know: playing on is the safer guess).
     */
    static Side kicker(PlayMode m) {
        Side owner = m.owner();
        if (owner == null) return null;
        // offside_left is an offence by the left team: the right team takes the free kick.
        return m == PlayMode.OFFSIDE_LEFT || m == PlayMode.OFFSIDE_RIGHT ? owner.opposite() : owner;
    }
}

package phalanx.comm.team;

/**
 * What the coordinator can tell a field player to do: the actions of thesis 4.6 that 5.1-5.12 assign
 * (On Ball for the player on the ball, Walk to Coordinate for active and support positions, Turn to
 * Localize and Stand Up for the inactive subset, Look Straight in wait mode). The wire code is 4 bits,
 * fixed per action so old and new players agree; codes 11-15 are free for new actions.
 */
public enum ActionId {
    /** 4.6.1: stand, head straight; the wait mode (5.2) before a kick-off. */
    LOOK_STRAIGHT(0, Params.NONE),
    /** 4.6.1: pan the head until the ball shows. */
    LOOK_FOR_BALL(1, Params.NONE),
    /** 4.6.1: turn the body until self-localization is confident again (lost players). */
    TURN_TO_LOCALIZE(2, Params.NONE),
    /** 4.6.1: get up after a confirmed fall. */
    STAND_UP(3, Params.NONE),
    /** 4.6.1: turn the body towards the ball. */
    TURN_TO_BALL(4, Params.NONE),
    /** 4.6.2: walk to the ball and stop close enough to kick. */
    WALK_TO_BALL(5, Params.NONE),
    /** 4.6.2: walk to the ball, face the opponent's goal and kick (the on-ball player, 5.8). */
    ON_BALL(6, Params.NONE),
    /** 4.6.2: walk to (x, y) and turn to the orientation (active and support positions, 5.7-5.12). */
    WALK_TO_COORDINATE(7, Params.POSE),
    /** 4.6.2: walk along a field-frame direction until told otherwise. */
    WALK_TO_DIRECTION(8, Params.DIRECTION),
    /** 4.6.2: dribble the ball along a field-frame direction. */
    DRIBBLE_TO_DIRECTION(9, Params.DIRECTION),
    /** 4.6.2: find the opponent's goal by scanning. */
    FIND_OPPONENT_GOAL(10, Params.NONE);

    /** Which parameters an action carries on the wire. */
    public enum Params {
        /** Nothing: 8 bits with recipient and id. */
        NONE,
        /** A field-frame orientation: 16 bits. */
        DIRECTION,
        /** Target x, y and orientation: 36 bits. */
        POSE
    }

    private static final ActionId[] BY_CODE = new ActionId[16];

    static {
        for (ActionId a : values()) {
            if (BY_CODE[a.code] != null) throw new ExceptionInInitializerError("two actions with code " + a.code);
            BY_CODE[a.code] = a;
        }
    }

    private final int code;
    private final Params params;

    ActionId(int code, Params params) {
        this.code = code;
        this.params = params;
    }

    public int code() { return code; }

    public Params params() { return params; }

    /** The action with this wire code, or null for a code this player does not know. */
    static ActionId ofCode(int code) {
        return code >= 0 && code < BY_CODE.length ? BY_CODE[code] : null;
    }
}

package phalanx.comm.perception;

/** Play modes of rcssserver3d 0.7.x (soccertypes.h), by their wire names. */
public enum PlayMode {
    BEFORE_KICK_OFF("BeforeKickOff"),
    KICK_OFF_LEFT("KickOff_Left"), KICK_OFF_RIGHT("KickOff_Right"),
    PLAY_ON("PlayOn"),
    KICK_IN_LEFT("KickIn_Left"), KICK_IN_RIGHT("KickIn_Right"),
    CORNER_KICK_LEFT("corner_kick_left"), CORNER_KICK_RIGHT("corner_kick_right"),
    GOAL_KICK_LEFT("goal_kick_left"), GOAL_KICK_RIGHT("goal_kick_right"),
    OFFSIDE_LEFT("offside_left"), OFFSIDE_RIGHT("offside_right"),
    GAME_OVER("GameOver"),
    GOAL_LEFT("Goal_Left"), GOAL_RIGHT("Goal_Right"),
    FREE_KICK_LEFT("free_kick_left"), FREE_KICK_RIGHT("free_kick_right"),
    DIRECT_FREE_KICK_LEFT("direct_free_kick_left"), DIRECT_FREE_KICK_RIGHT("direct_free_kick_right"),
    PASS_LEFT("pass_left"), PASS_RIGHT("pass_right"),
    /** A name this client does not know (a newer server); the raw name is in {@link GameState}. */
    UNKNOWN("?");

    private static final PlayMode[] VALUES = values();
    private final String wireName;

    PlayMode(String wireName) { this.wireName = wireName; }

    public String wireName() { return wireName; }

    /** The mode with this wire name, or {@link #UNKNOWN}. */
    public static PlayMode fromWire(CharSequence name) {
        for (PlayMode m : VALUES) {
            if (m != UNKNOWN && m.wireName.contentEquals(name)) return m;
        }
        return UNKNOWN;
    }

    /** The side that owns this set piece or kick-off, or null when it belongs to neither. */
    public Side owner() {
        String n = wireName.toLowerCase();
        if (n.endsWith("_left")) return Side.LEFT;
        if (n.endsWith("_right")) return Side.RIGHT;
        return null;
    }

    /** Beam is honoured before kick-off and after a goal (DESIGN.md, protocol facts). */
    public boolean allowsBeam() {
        return this == BEFORE_KICK_OFF || this == GOAL_LEFT || this == GOAL_RIGHT;
    }
}

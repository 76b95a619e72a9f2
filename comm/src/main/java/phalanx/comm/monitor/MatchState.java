package phalanx.comm.monitor;

import phalanx.comm.perception.PlayMode;

/**
 * The game as the monitor port reports it: the header of each monitor message carries what
 * changed ({@code (time t)}, {@code (play_mode n)}, {@code (score_left n)}, {@code (team_left NAME)},
 * ...), the first message all of it. Unknown team names are null until the server names them.
 */
public record MatchState(double time, int half, int scoreLeft, int scoreRight, PlayMode playMode,
                         String teamLeft, String teamRight) {

    public static final MatchState INITIAL = new MatchState(0, 1, 0, 0, PlayMode.BEFORE_KICK_OFF, null, null);
}

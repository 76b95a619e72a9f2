package phalanx.match;

import java.util.ArrayList;
import java.util.List;

/**
 * The game state in rcssservermj's monitor messages (RSMP, server/remote_monitor.py and
 * games/soccer/sim/soccer_state_info.py; match/src/test/resources/rcssservermj/README.md):
 * {@code (gs 1 0)(time T)(half H)(score_left A)(score_right B)(play_mode INDEX)}, the team names in full-state
 * messages only, and the play-mode names, once, in {@code (ge 1 0 ... (play_modes ...))}. Stateful: it keeps the
 * names and the last state across messages. Of the scene graph only the ball's place is read ({@link #ball}).
 */
public final class MjMonitor {
    /** One game state. Team names are null until a full-state message has named them. */
    public record State(double time, int half, int scoreLeft, int scoreRight, String playMode,
                        String teamLeft, String teamRight) {
        public boolean gameOver() { return "GameOver".equals(playMode); }
    }

    /** rcsssmj 0.2.1's order (games/soccer/play_mode.py), until a ge block names them: the first state can come first. */
    static final List<String> DEFAULT_MODES = List.of("BeforeKickOff", "KickOff_Left", "KickOff_Right", "PlayOn",
            "KickIn_Left", "KickIn_Right", "corner_kick_left", "corner_kick_right", "goal_kick_left", "goal_kick_right",
            "offside_left", "offside_right", "GameOver", "Goal_Left", "Goal_Right", "free_kick_left", "free_kick_right",
            "direct_free_kick_left", "direct_free_kick_right", "penalty_kick_left", "penalty_kick_right",
            "penalty_shoot_left", "penalty_shoot_right");

    private List<String> modes = DEFAULT_MODES;
    private String teamLeft, teamRight;
    private State state;

    /** Reads one monitor message; returns the state it carried, or the last one if it had none. */
    public State accept(String message) {
        String ge = block(message, "(ge 1 0)");
        if (ge != null) {
            String pm = value(ge, "play_modes");
            if (pm != null) modes = List.of(pm.trim().split("\\s+"));
        }
        String gs = block(message, "(gs 1 0)");
        if (gs == null) return state;
        String tl = value(gs, "team_left"), tr = value(gs, "team_right");
        if (tl != null) teamLeft = named(tl);
        if (tr != null) teamRight = named(tr);
        int index = (int) number(gs, "play_mode", -1);
        String mode = index >= 0 && index < modes.size() ? modes.get(index) : "mode " + index;
        state = new State(number(gs, "time", Double.NaN), (int) number(gs, "half", 0), (int) number(gs, "score_left", 0),
                (int) number(gs, "score_right", 0), mode, teamLeft, teamRight);
        return state;
    }

    public State state() { return state; }

    /**
     * The ball's position in a monitor message, or null when the message does not move it. The scene graph
     * ({@code (sg 1 0)full|diff}, sent every second cycle) starts with the root node, whose first child is the ball's node
     * ({@code (nd DSC(ball) ...)} in full states), whose first child holds its transform
     * {@code (nd TRF(SLT m0 .. m15))}, column-major, the translation in m12..m14. A diff leaves out the TRF of a
     * node that did not change, so the third {@code (nd} after {@code (sg 1 0)} is the ball's transform node in
     * both (seen in match/src/test/resources/rcssservermj/monitor-kickoff.txt).
     */
    public static double[] ball(String m) {
        int at = m.indexOf("(sg 1 0)");
        if (at < 0) return null;
        for (int k = 0; k < 3; k++) {
            at = m.indexOf("(nd", at + 1);
            if (at < 0) return null;
        }
        String trf = " TRF(SLT ";
        if (!m.startsWith(trf, at + 3)) return null;
        int start = at + 3 + trf.length(), end = m.indexOf(')', start);
        if (end < 0) return null;
        String[] v = m.substring(start, end).trim().split("\\s+");
        if (v.length != 16) return null;
        try {
            return new double[]{Double.parseDouble(v[12]), Double.parseDouble(v[13]), Double.parseDouble(v[14])};
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** {@code <LEFT>} and {@code <RIGHT>} stand for a side no team has joined yet. */
    private static String named(String v) {
        return v.startsWith("<") ? null : v;
    }

    /** The text after {@code head} up to the closing parenthesis of the list that {@code head} opens. */
    private static String block(String m, String head) {
        int at = m.indexOf(head);
        if (at < 0) return null;
        int depth = 1;
        for (int i = at + head.length(); i < m.length(); i++) {
            char c = m.charAt(i);
            if (c == '(') depth++;
            else if (c == ')' && --depth == 0) return m.substring(at + head.length(), i);
        }
        return null;   // truncated: no state from this message
    }

    /** The atom(s) of a flat {@code (key value)} child, or null. */
    private static String value(String block, String key) {
        int at = block.indexOf("(" + key + " ");
        if (at < 0) return null;
        int end = block.indexOf(')', at);
        return end < 0 ? null : block.substring(at + key.length() + 2, end).trim();
    }

    private static double number(String block, String key, double otherwise) {
        String v = value(block, key);
        if (v == null) return otherwise;
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException e) {
            return otherwise;
        }
    }

    /** Every player that joined or left, from the server's log lines "Player TEAM #N joined the game." / "left". */
    public static List<String[]> rosterLines(List<String> serverLog) {
        List<String[]> out = new ArrayList<>();
        for (String line : serverLog) {
            int p = line.indexOf("Player ");
            if (p < 0) continue;
            boolean joined = line.endsWith(" joined the game."), left = line.endsWith(" left the game.");
            if (!joined && !left) continue;
            String who = line.substring(p + 7, line.length() - (joined ? 17 : 15));
            int hash = who.lastIndexOf(" #");
            if (hash < 0) continue;
            out.add(new String[] {who.substring(0, hash), who.substring(hash + 2), joined ? "joined" : "left"});
        }
        return out;
    }
}

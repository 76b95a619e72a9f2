package phalanx.comm.monitor;

import phalanx.comm.perception.PlayMode;

import java.util.ArrayList;
import java.util.List;

/**
 * Reads the game-state header that starts every monitor message (the part before {@code (RSG} or
 * {@code (RDS}) and folds it into a {@link MatchState}. The play mode is an index into the
 * {@code play_modes} list of the first message; 0.7.x servers use the order of
 * {@link PlayMode}, which is the fallback. Fields it does not know are skipped.
 */
public final class MonitorHeader {
    private List<PlayMode> modes = List.of(PlayMode.values());

    /** The state after applying this message's header; a malformed header leaves it unchanged. */
    public MatchState apply(MatchState s, String message) {
        int i = message.indexOf('(');
        if (i != 0 || message.length() < 2 || message.charAt(1) != '(') return s;
        double time = s.time();
        int half = s.half(), sl = s.scoreLeft(), sr = s.scoreRight();
        PlayMode pm = s.playMode();
        String tl = s.teamLeft(), tr = s.teamRight();
        int pos = 1;
        while (pos < message.length() && message.charAt(pos) == '(') {
            int close = message.indexOf(')', pos);
            if (close < 0) return s;
            String[] f = message.substring(pos + 1, close).trim().split("\\s+");
            pos = close + 1;
            if (f.length < 2) continue;
            try {
                switch (f[0]) {
                    case "time" -> time = Double.parseDouble(f[1]);
                    case "half" -> half = Integer.parseInt(f[1]);
                    case "score_left" -> sl = Integer.parseInt(f[1]);
                    case "score_right" -> sr = Integer.parseInt(f[1]);
                    case "team_left" -> tl = f[1];
                    case "team_right" -> tr = f[1];
                    case "play_mode" -> {
                        int n = Integer.parseInt(f[1]);
                        pm = n >= 0 && n < modes.size() ? modes.get(n) : PlayMode.UNKNOWN;
                    }
                    case "play_modes" -> {
                        List<PlayMode> m = new ArrayList<>();
                        for (int k = 1; k < f.length; k++) m.add(PlayMode.fromWire(f[k]));
                        modes = List.copyOf(m);
                    }
                    default -> { }
                }
            } catch (NumberFormatException e) {
                return s;
            }
        }
        return new MatchState(time, half, sl, sr, pm, tl, tr);
    }
}

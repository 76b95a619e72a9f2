package phalanx.comm.perception;

import java.util.Arrays;
import java.util.List;

/**
 * The See perceptor (every third cycle). Landmarks are indexed by {@link Landmark#ordinal()},
 * null when not seen. {@code myPos}, {@code myOrienDeg} and {@code ballPos} are only sent by
 * servers with position sense switched on (never in competition); null / NaN otherwise.
 */
public record Vision(Polar[] landmarks, Polar ball, List<SeenPlayer> players, List<SeenLine> lines,
                     Vector3 myPos, double myOrienDeg, Vector3 ballPos) {

    public Polar landmark(Landmark l) { return landmarks[l.ordinal()]; }

    public int landmarkCount() {
        int n = 0;
        for (Polar p : landmarks) if (p != null) n++;
        return n;
    }

    @Override public boolean equals(Object o) {
        return o instanceof Vision v && Arrays.equals(v.landmarks, landmarks) && java.util.Objects.equals(v.ball, ball)
                && v.players.equals(players) && v.lines.equals(lines);
    }
    @Override public int hashCode() { return Arrays.hashCode(landmarks); }
}

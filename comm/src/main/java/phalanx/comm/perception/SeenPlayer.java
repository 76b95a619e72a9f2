package phalanx.comm.perception;

import java.util.Arrays;

/**
 * A player in the See perceptor: team name, uniform number (0 when the server left it out) and
 * each visible body part, indexed by {@link BodyPart#ordinal()} (null when that part is not seen).
 */
public record SeenPlayer(String team, int id, Polar[] parts) {

    public Polar part(BodyPart p) { return parts[p.ordinal()]; }

    @Override public boolean equals(Object o) {
        return o instanceof SeenPlayer s && s.id == id && s.team.equals(team) && Arrays.equals(s.parts, parts);
    }
    @Override public int hashCode() { return team.hashCode() * 31 + id; }
    @Override public String toString() { return "SeenPlayer[" + team + " " + id + " " + Arrays.toString(parts) + "]"; }
}

package phalanx.coordination;

import java.util.List;
import phalanx.coordination.beliefs.GlobalBeliefs;
import phalanx.coordination.formation.Formation;
import phalanx.coordination.formation.Role;
import phalanx.coordination.subsets.Subsets;
import phalanx.model.field.Vector2;

/**
 * The result of one coordination round: an assignment per reporting player plus what led to it (for the
 * next round's hysteresis, for debugging and for pictures).
 *
 * @param mode             the coordination mode
 * @param beliefs          the fused beliefs
 * @param subsets          the subsets after the active mapping (active players without a candidate
 *                         position move to support)
 * @param defensive        the active candidates are the defensive ones (ball in our half)
 * @param activeCandidates the candidate active positions (5.7), best first
 * @param formation        the formation for this ball (5.9)
 * @param droppedRoles     roles nobody takes, one per inactive or absent player (5.11)
 * @param assignments      one per reporting player, by uniform number
 * @param supportEvaluated mappings the support mapper scored
 */
public record TeamPlan(Mode mode, GlobalBeliefs beliefs, Subsets subsets, boolean defensive,
                       List<Vector2> activeCandidates, Formation formation, List<Role> droppedRoles,
                       List<Assignment> assignments, long supportEvaluated) {
    public TeamPlan {
        activeCandidates = List.copyOf(activeCandidates);
        droppedRoles = List.copyOf(droppedRoles);
        assignments = List.copyOf(assignments);
    }

    /** The assignment of this uniform number, or null. */
    public Assignment assignment(int id) {
        for (Assignment a : assignments) if (a.id() == id) return a;
        return null;
    }

    /** The on-ball player's uniform number, or 0. */
    public int onBall() {
        for (Assignment a : assignments) if (a.onBall()) return a.id();
        return 0;
    }

    public Vector2 ball() { return beliefs.ball(); }

    /** What the next round needs from this one. */
    public Memory memory() { return new Memory(onBall(), ball()); }

    public List<String> warnings() { return beliefs.warnings(); }
}

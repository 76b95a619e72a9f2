package phalanx.coordination.formation;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import phalanx.model.field.Vector2;

/**
 * Phases 5b and 5c of Algorithm 3. "Assign Team Roles" (thesis 5.10): the active players take the k
 * formation roles nearest the ball (k = number of active players), each the role nearest its own
 * coordination target (the cheapest of the k! pairings by summed distance; the thesis does not say how
 * the k roles are shared out). "Determine Support Positions" (5.11): of the remaining roles the support
 * players get the ones nearest the ball, one per support player; the farthest are dropped, one per
 * inactive player.
 *
 * @param activeRoles  role per active player, in the order given
 * @param supportRoles the support positions' roles, nearest the ball first
 * @param dropped      roles nobody takes, nearest the ball first
 */
public record RoleAssignment(List<Role> activeRoles, List<Role> supportRoles, List<Role> dropped) {

    /**
     * @param activeTargets the active players' coordination targets (the ball for the on-ball player)
     * @param supportCount  the number of support players
     */
    public static RoleAssignment assign(Formation f, Vector2 ball, List<Vector2> activeTargets, int supportCount) {
        List<Role> byDistance = new ArrayList<>();
        for (Role r : f.positions().keySet()) if (r != Role.GK) byDistance.add(r);
        byDistance.sort(Comparator.comparingDouble((Role r) -> f.position(r).distanceTo(ball)).thenComparing(r -> r));
        int k = Math.min(activeTargets.size(), byDistance.size());
        List<Role> near = byDistance.subList(0, k);
        Role[] best = new Role[k];
        pair(near, activeTargets, f, new Role[k], new boolean[k], 0, 0, best, new double[]{Double.POSITIVE_INFINITY});
        List<Role> rest = byDistance.subList(k, byDistance.size());
        int s = Math.min(supportCount, rest.size());
        return new RoleAssignment(List.of(best), List.copyOf(rest.subList(0, s)), List.copyOf(rest.subList(s, rest.size())));
    }

    private static void pair(List<Role> roles, List<Vector2> targets, Formation f, Role[] cur, boolean[] used,
                             int i, double cost, Role[] best, double[] bestCost) {
        if (cost >= bestCost[0]) return;
        if (i == cur.length) { bestCost[0] = cost; System.arraycopy(cur, 0, best, 0, cur.length); return; }
        for (int r = 0; r < roles.size(); r++) {
            if (used[r]) continue;
            used[r] = true;
            cur[i] = roles.get(r);
            pair(roles, targets, f, cur, used, i + 1, cost + targets.get(i).distanceTo(f.position(roles.get(r))), best, bestCost);
            used[r] = false;
        }
    }

    /** Role per uniform number, for the given active ids (same order as the targets). */
    public Map<Integer, Role> activeById(List<Integer> activeIds) {
        Map<Integer, Role> m = new LinkedHashMap<>();
        for (int i = 0; i < activeIds.size(); i++) m.put(activeIds.get(i), activeRoles.get(i));
        return m;
    }
}

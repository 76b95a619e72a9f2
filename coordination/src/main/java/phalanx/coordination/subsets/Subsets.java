package phalanx.coordination.subsets;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import phalanx.coordination.Mode;
import phalanx.coordination.beliefs.GlobalBeliefs;
import phalanx.coordination.beliefs.PlayerBelief;

/**
 * Phase 2 of Algorithm 3, "Determine Coordination Subsets" (thesis 5.5): the goalkeeper; the inactive
 * players (type X, fallen); the active players (the {@code activeCount} nearest the ball); the rest
 * support. Modes (5.2) override this: in Support mode nobody is active, in Wait mode every field player
 * is inactive. Lists hold uniform numbers; active players are ordered nearest first.
 *
 * @param goalkeeper the goalkeeper's uniform number, or 0 when it did not report
 */
public record Subsets(int goalkeeper, List<Integer> inactive, List<Integer> active, List<Integer> support) {
    public Subsets {
        inactive = List.copyOf(inactive);
        active = List.copyOf(active);
        support = List.copyOf(support);
    }

    public Subset of(int id) {
        if (id == goalkeeper && id != 0) return Subset.GOALKEEPER;
        if (active.contains(id)) return Subset.ACTIVE;
        if (support.contains(id)) return Subset.SUPPORT;
        if (inactive.contains(id)) return Subset.INACTIVE;
        return null;
    }

    public static Subsets split(GlobalBeliefs beliefs, Mode mode, int goalkeeperId, int activeCount) {
        int gk = 0;
        List<Integer> inactive = new ArrayList<>();
        List<PlayerBelief> usable = new ArrayList<>();
        for (PlayerBelief p : beliefs.players()) {
            if (p.id() == goalkeeperId) gk = p.id();
            else if (mode == Mode.WAIT || !p.usable()) inactive.add(p.id());
            else usable.add(p);
        }
        usable.sort(Comparator.comparingDouble(PlayerBelief::ballDistance).thenComparingInt(PlayerBelief::id));
        int nActive = mode == Mode.ACTIVE ? Math.min(activeCount, usable.size()) : 0;
        List<Integer> active = new ArrayList<>(nActive), support = new ArrayList<>();
        for (int i = 0; i < usable.size(); i++) (i < nActive ? active : support).add(usable.get(i).id());
        support.sort(null);
        return new Subsets(gk, inactive, active, support);
    }

    /** The same subsets with some active players moved to support (when they found no candidate position). */
    public Subsets demote(List<Integer> ids) {
        List<Integer> a = new ArrayList<>(active), s = new ArrayList<>(support);
        a.removeAll(ids);
        s.addAll(ids);
        s.sort(null);
        return new Subsets(goalkeeper, inactive, a, s);
    }
}

package phalanx.coordination.beliefs;

import java.util.List;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * The fused world state the coordination works from (thesis 5.4).
 *
 * @param field            field geometry
 * @param ball             the global ball belief
 * @param ballObservations how many type C observations it fuses (0: fallback or previous ball)
 * @param players          one belief per reporting player, in uniform-number order
 * @param warnings         reports that were rejected or repaired, one readable line each
 */
public record GlobalBeliefs(FieldSpec field, Vector2 ball, int ballObservations, List<PlayerBelief> players,
                            List<String> warnings) {
    public GlobalBeliefs {
        players = List.copyOf(players);
        warnings = List.copyOf(warnings);
    }

    /** The belief about this uniform number, or null. */
    public PlayerBelief player(int id) {
        for (PlayerBelief p : players) if (p.id() == id) return p;
        return null;
    }
}

package phalanx.coordination.formation;

import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;
import phalanx.model.field.Vector2;

/** A team formation: one position per role, in the team's own frame. */
public record Formation(Map<Role, Vector2> positions) {
    public Formation {
        positions = Collections.unmodifiableMap(new EnumMap<>(positions));
    }

    public Vector2 position(Role r) { return positions.get(r); }
}

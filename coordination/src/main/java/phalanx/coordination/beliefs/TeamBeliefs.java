package phalanx.coordination.beliefs;

import java.util.List;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * What the coordinator knows at the start of a round: the field, and the latest report of every player
 * that reported (the coordinator's own beliefs included, as the goalkeeper's report).
 *
 * @param field        field geometry; {@code field.players()} bounds the uniform numbers
 * @param reports      at most one per player; later duplicates replace earlier ones
 * @param fallbackBall the coordinator's own filtered ball, used only when no player reports one (may be null)
 */
public record TeamBeliefs(FieldSpec field, List<PlayerReport> reports, Vector2 fallbackBall) {
    public TeamBeliefs {
        if (field == null) throw new IllegalArgumentException("field is null");
        // Copied as is, nulls included: the update drops them with a message rather than throwing here.
        reports = reports == null ? List.of() : java.util.Collections.unmodifiableList(new java.util.ArrayList<>(reports));
    }

    public TeamBeliefs(FieldSpec field, List<PlayerReport> reports) { this(field, reports, null); }
}

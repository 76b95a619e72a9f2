package phalanx.coordination.features;

import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * The value of a spot of the field (thesis 5.6): CurrentSide · x · (W/2 − |y|). In the team's own frame
 * the opponent goal is always at +x, so CurrentSide is +1: high near their goal, low near ours.
 */
public final class FieldUtility {
    private FieldUtility() {}

    public static double of(double x, double y, FieldSpec field) {
        return x * (field.halfWidth() - Math.abs(y));
    }

    public static double of(Vector2 p, FieldSpec field) { return of(p.x(), p.y(), field); }
}

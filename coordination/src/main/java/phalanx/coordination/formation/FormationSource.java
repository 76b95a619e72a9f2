package phalanx.coordination.formation;

import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * How a coordination round lays out the team formation for the ball (phase 5a, thesis 5.9): the thesis generator
 * ({@link FormationGenerator}) on SimSpark's fields, the same stretched to rcssservermj's 55 x 36 m field for 7 players
 * ({@link StretchedFormation}), where the thesis generator has no 7-player formation.
 */
@FunctionalInterface
public interface FormationSource {
    /** The formation for the ball at this place of this field (own frame). */
    Formation generate(Vector2 ball, FieldSpec field);
}

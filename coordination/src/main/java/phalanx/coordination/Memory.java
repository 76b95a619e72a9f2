package phalanx.coordination;

import phalanx.model.field.Vector2;

/**
 * What one round carries into the next: the on-ball player, favoured by the hysteresis of 5.8, and the
 * ball, used when nobody reports one.
 *
 * @param onBall the previous on-ball player's uniform number, 0 for none
 * @param ball   the previous global ball, or null
 */
public record Memory(int onBall, Vector2 ball) {
    /** No previous round. */
    public static final Memory NONE = new Memory(0, null);
}

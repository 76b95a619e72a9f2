package phalanx.comm.team;

/**
 * One player's assignment from the coordinator (thesis 5.3, the "a" message): the recipient's uniform
 * number, the action and its parameters in the field frame of our team (metres, degrees, 0° = +x,
 * counter-clockwise positive). Parameters the action does not carry are 0.
 */
public record Action(int recipient, ActionId id, double x, double y, double thetaDeg) {

    public Action {
        if (id == null) throw new IllegalArgumentException("action id is null");
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(thetaDeg)) {
            throw new IllegalArgumentException("action parameters must be finite, got " + x + ", " + y + ", " + thetaDeg);
        }
    }

    /** An action without parameters. */
    public static Action of(int recipient, ActionId id) {
        if (id.params() != ActionId.Params.NONE) throw new IllegalArgumentException(id + " needs parameters");
        return new Action(recipient, id, 0, 0, 0);
    }

    /** An action with a direction (Walk/Dribble to Direction). */
    public static Action towards(int recipient, ActionId id, double thetaDeg) {
        if (id.params() != ActionId.Params.DIRECTION) throw new IllegalArgumentException(id + " does not take a direction");
        return new Action(recipient, id, 0, 0, thetaDeg);
    }

    /** Walk to Coordinate (x, y, θ). */
    public static Action walkTo(int recipient, double x, double y, double thetaDeg) {
        return new Action(recipient, ActionId.WALK_TO_COORDINATE, x, y, thetaDeg);
    }
}

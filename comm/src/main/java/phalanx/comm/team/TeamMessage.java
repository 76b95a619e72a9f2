package phalanx.comm.team;

import java.util.List;

/**
 * The messages of thesis 5.3, as values. {@link TeamMessageCodec} turns them into at most 20
 * characters and back; the field layout is documented there. Positions are metres in our team's own
 * field frame, angles degrees; on the wire positions are kept to 4 cm and angles to 1.41°.
 */
public sealed interface TeamMessage {

    /** "i": a field player announces itself to the coordinator. */
    record Init(int sender) implements TeamMessage {
    }

    /**
     * "s": the coordinator starts a round; the field players report in the slots that follow, in
     * uniform-number order, one slot each.
     */
    record Start(int sender) implements TeamMessage {
    }

    /**
     * "e": the coordinator closes a round without actions to send; the next round's reports start
     * one slot later plus the pause. (When there are actions, the first action message closes the
     * round: that saves a slot.)
     */
    record End(int sender) implements TeamMessage {
    }

    /**
     * "a": some of the actions of one dispatch; {@code remaining} more action messages follow in the
     * next slots (0-7), so a player hearing any of them knows when the next round's reports start.
     */
    record Actions(int remaining, List<Action> actions) implements TeamMessage {
        public Actions {
            actions = List.copyOf(actions);
        }
    }

    /** The four coordination messages: what a field player believes, by how much it knows. */
    sealed interface Report extends TeamMessage {
        int sender();
    }

    /** "C": self pose and ball position, both known. */
    record Complete(int sender, double x, double y, double thetaDeg, double ballX, double ballY) implements Report {
    }

    /** "L": self pose known; the ball is not in view, so no (possibly stale) ball belief is sent. */
    record Location(int sender, double x, double y, double thetaDeg) implements Report {
    }

    /** "B": the ball relative to the body (distance m, angle ° counter-clockwise from straight ahead); self pose unknown. */
    record Ball(int sender, double distance, double angleDeg) implements Report {
    }

    /** "X": neither self nor ball known, or fallen: the player joins the inactive subset. */
    record Unaware(int sender, boolean fallen) implements Report {
    }
}

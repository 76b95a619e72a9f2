package phalanx.agent.roboviz;

import phalanx.comm.perception.Side;
import phalanx.coordination.Assignment;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.model.field.Vector2;

/**
 * Draws the goalkeeper's last coordination round (thesis chapter 5) under
 * {@code animated.phalanx.<team>.plan}: the active candidate positions, each player's assignment as
 * a line from where it reported to its target, coloured by subset, and its role (or "ball") as a
 * label. Drawn once per round, when the plan changes.
 */
public final class PlanDrawing {
    private static final int CANDIDATE = 0xff9900, ON_BALL = 0xff0000, ACTIVE = 0xffcc00, SUPPORT = 0x00ccff, OTHER = 0x999999;

    private PlanDrawing() {}

    public static void draw(RoboViz rv, TeamPlan plan, Side side, String team) {
        String set = "animated.phalanx." + team + ".plan";
        int flip = side == Side.RIGHT ? -1 : 1;
        for (Vector2 c : plan.activeCandidates()) rv.point(flip * c.x(), flip * c.y(), 0.02, 4, CANDIDATE, set);
        for (Assignment a : plan.assignments()) {
            PlayerBelief from = plan.beliefs().player(a.id());
            if (a.target() == null) continue;
            int rgb = switch (a.action()) {
                case ON_BALL -> ON_BALL;
                case ACTIVE_POSITION -> ACTIVE;
                case SUPPORT_POSITION -> SUPPORT;
                default -> OTHER;
            };
            if (from != null && from.position() != null) {
                rv.line(flip * from.position().x(), flip * from.position().y(), 0.05,
                        flip * a.target().x(), flip * a.target().y(), 0.05, 2, rgb, set);
            }
            String label = a.onBall() ? a.id() + " ball" : a.id() + " " + (a.role() == null ? a.action().name() : a.role().name());
            rv.annotation(label, flip * a.target().x(), flip * a.target().y(), 0.6, rgb, set);
        }
        rv.swap(set);
        rv.flush();
    }
}

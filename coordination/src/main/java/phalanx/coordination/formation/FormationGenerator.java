package phalanx.coordination.formation;

import java.util.EnumMap;
import java.util.Map;
import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * Phase 5a of Algorithm 3, "Generate Team Formation" (thesis 5.9): a formation as a function of the ball.
 * <ul>
 * <li>Defenders: DC on the segment from our goal to the ball, 2 to 3 m from the goal in proportion to the
 *     segment's length; DL and DR either side of DC across that segment, a little up it.</li>
 * <li>Forwards: FC just behind the ball but never below {@code forwardMinX} (near the middle); FL and FR
 *     either side of FC and a little behind, at a bearing and distance that follow the ball: the pair
 *     turns a third of the way towards the opponent goal and spreads wider as the ball advances.</li>
 * <li>9 players: ML and MR near the forwards when the ball is in their half, in front of the defence
 *     when it is in ours.</li>
 * <li>11 players (DESIGN.md, "Gaps in the thesis text"): FS a fixed distance behind FC, MC the same
 *     distance behind FS, ML and MR either side of MC at a bearing and distance that follow MC's
 *     position (wider near the middle of the field).</li>
 * <li>GK: on our goal line, shifted a little towards the ball's side (its own FSM decides, 5.13).</li>
 * </ul>
 * Each group (defenders; forwards with FS; midfielders) that would cross a line is moved inside as a
 * whole, keeping its shape and its left and right, so that nothing ends up beyond {@code inset} from the
 * lines and no two roles pile up in a corner.
 */
public final class FormationGenerator {
    private static final Role[] ROLES = Role.values();

    private FormationGenerator() {}

    public static Formation generate(Vector2 ballIn, FieldSpec field, FormationConfig c) {
        double hl = field.halfLength(), hw = field.halfWidth();
        double hx = hl - c.inset(), hy = hw - c.inset();
        Vector2 ball = field.clamp(ballIn.isFinite() ? ballIn : Vector2.ZERO, 0);
        double progress = (ball.x() + hl) / field.length();
        Map<Role, Vector2> p = new EnumMap<>(Role.class);

        // Defence: along the goal-ball line.
        Vector2 goal = field.ownGoal();
        Vector2 v = ball.minus(goal);
        double len = v.norm();
        Vector2 u = len > 1e-9 ? v.times(1 / len) : new Vector2(1, 0);
        Vector2 left = new Vector2(-u.y(), u.x());
        double maxLen = Math.hypot(field.length(), hw);
        Vector2 dc = goal.plus(u.times(c.defenderNear() + (c.defenderFar() - c.defenderNear()) * Math.min(1, len / maxLen)));
        Vector2[] defence = {dc,
                dc.plus(left.times(c.defenderSpread())).plus(u.times(c.defenderStepUp())),
                dc.minus(left.times(c.defenderSpread())).plus(u.times(c.defenderStepUp()))};
        shiftInside(defence, hx, hy);
        p.put(Role.DC, defence[0]);
        p.put(Role.DL, defence[1]);
        p.put(Role.DR, defence[2]);

        // Forwards (and, for 11, the Forward Support behind FC): the wings turn a third of the way
        // towards the opponent goal (at most 20°) and spread as the ball advances.
        Vector2 fc = new Vector2(Math.max(ball.x() - c.forwardBehind(), c.forwardMinX()), ball.y());
        double tilt = Math.max(-20, Math.min(20, field.opponentGoal().minus(fc).angleDeg() / 3));
        double wing = c.wingBase() + c.wingGrowth() * progress;
        boolean eleven = field.players() == 11;
        Vector2[] forwards = {fc, fc.plus(Vector2.polar(wing, tilt + c.wingAngle())),
                fc.plus(Vector2.polar(wing, tilt - c.wingAngle())),
                fc.minus(new Vector2(c.supportBehind(), 0))};
        shiftInside(forwards, hx, hy);
        p.put(Role.FC, forwards[0]);
        p.put(Role.FL, forwards[1]);
        p.put(Role.FR, forwards[2]);

        Vector2[] midfield;
        if (eleven) {
            p.put(Role.FS, forwards[3]);
            Vector2 mc = forwards[3].minus(new Vector2(c.supportBehind(), 0));
            double mSpread = c.midfieldSpread() + c.wingGrowth() * (1 - Math.min(1, Math.abs(mc.y()) / hw));
            double mTilt = Math.max(-20, Math.min(20, field.opponentGoal().minus(mc).angleDeg() / 3));
            midfield = new Vector2[]{mc, mc.plus(Vector2.polar(mSpread, mTilt + c.midfieldAngle())),
                    mc.plus(Vector2.polar(mSpread, mTilt - c.midfieldAngle()))};
        } else {
            Vector2 centre, side;
            if (ball.x() >= 0) {
                centre = forwards[0].minus(new Vector2(c.midfieldBehindForwards(), 0));
                side = new Vector2(0, 1);
            } else {
                centre = defence[0].plus(u.times(c.midfieldAhead()));
                side = left;
            }
            midfield = new Vector2[]{centre, centre.plus(side.times(c.midfieldSpread())),
                    centre.minus(side.times(c.midfieldSpread()))};
        }
        shiftInside(midfield, hx, hy);
        if (eleven) p.put(Role.MC, midfield[0]);
        p.put(Role.ML, midfield[1]);
        p.put(Role.MR, midfield[2]);

        double gy = Math.max(-(field.goalWidth() / 2 - 0.2), Math.min(field.goalWidth() / 2 - 0.2, ball.y() * 0.2));
        p.put(Role.GK, new Vector2(-hl + c.goalkeeperDepth(), gy));

        for (Role r : ROLES) {   // not over entrySet(): an EnumMap makes an entry object per step
            Vector2 at = p.get(r);
            if (at != null) p.put(r, field.clamp(at, c.inset()));
        }
        return new Formation(p);
    }

    /**
     * Moves a group of positions as one, by the least translation that puts all of them inside
     * [-hx, hx] x [-hy, hy], so the group keeps its shape and its left and right.
     */
    static void shiftInside(Vector2[] group, double hx, double hy) {
        double minX = Double.POSITIVE_INFINITY, maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
        for (Vector2 q : group) {
            minX = Math.min(minX, q.x()); maxX = Math.max(maxX, q.x());
            minY = Math.min(minY, q.y()); maxY = Math.max(maxY, q.y());
        }
        double dx = maxX > hx ? hx - maxX : minX < -hx ? -hx - minX : 0;
        double dy = maxY > hy ? hy - maxY : minY < -hy ? -hy - minY : 0;
        if (dx == 0 && dy == 0) return;
        Vector2 d = new Vector2(dx, dy);
        for (int i = 0; i < group.length; i++) group[i] = group[i].plus(d);
    }
}

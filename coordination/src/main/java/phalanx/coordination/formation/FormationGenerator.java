package phalanx.coordination.formation;

import java.util.EnumMap;
import java.util.Map;
import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.localization.field.FieldSpec;
import phalanx.localization.field.Vector2;

/**
 * Phase 5a of Algorithm 3, "Generate Team Formation" (thesis 5.9): a formation as a function of the ball.
 * <ul>
 * <li>Defenders: DC on the segment from our goal to the ball, 2 to 3 m from the goal in proportion to the
 *     segment's length; DL and DR either side of DC across that segment, a little up it.</li>
 * <li>Forwards: FC just behind the ball but never below {@code forwardMinX} (near the middle); FL and FR
 *     either side of FC, at a bearing and distance that follow the ball: they open around the line from
 *     FC to the opponent goal and spread wider as the ball advances.</li>
 * <li>9 players: ML and MR near the forwards when the ball is in their half, in front of the defence
 *     when it is in ours.</li>
 * <li>11 players (DESIGN.md, "Gaps in the thesis text"): FS a fixed distance behind FC, MC the same
 *     distance behind FS, ML and MR either side of MC at a bearing and distance that follow MC's
 *     position (wider near the middle of the field).</li>
 * <li>GK: on our goal line, shifted a little towards the ball's side (its own FSM decides, 5.13).</li>
 * </ul>
 * Positions that would leave the field are reflected back off the line they cross and then clamped
 * {@code inset} inside the lines, so a wing pushed into a corner does not land on top of FC.
 */
public final class FormationGenerator {
    private FormationGenerator() {}

    public static Formation generate(Vector2 ballIn, FieldSpec field, FormationConfig c) {
        double hl = field.halfLength(), hw = field.halfWidth();
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
        p.put(Role.DC, dc);
        p.put(Role.DL, dc.plus(left.times(c.defenderSpread())).plus(u.times(c.defenderStepUp())));
        p.put(Role.DR, dc.minus(left.times(c.defenderSpread())).plus(u.times(c.defenderStepUp())));

        // Forwards.
        Vector2 fc = new Vector2(Math.max(ball.x() - c.forwardBehind(), c.forwardMinX()), ball.y());
        double towardsGoal = field.opponentGoal().minus(fc).angleDeg();
        double wing = c.wingBase() + c.wingGrowth() * progress;
        p.put(Role.FC, fc);
        p.put(Role.FL, fc.plus(Vector2.polar(wing, towardsGoal + c.wingAngle())));
        p.put(Role.FR, fc.plus(Vector2.polar(wing, towardsGoal - c.wingAngle())));

        if (field.players() == 11) {
            Vector2 fs = fc.minus(new Vector2(c.supportBehind(), 0));
            Vector2 mc = fs.minus(new Vector2(c.supportBehind(), 0));
            double mAngle = field.opponentGoal().minus(mc).angleDeg();
            double mSpread = c.midfieldSpread() + c.wingGrowth() * (1 - Math.min(1, Math.abs(mc.y()) / hw));
            p.put(Role.FS, fs);
            p.put(Role.MC, mc);
            p.put(Role.ML, mc.plus(Vector2.polar(mSpread, mAngle + c.midfieldAngle())));
            p.put(Role.MR, mc.plus(Vector2.polar(mSpread, mAngle - c.midfieldAngle())));
        } else {
            Vector2 centre, side;
            if (ball.x() >= 0) {
                centre = fc.minus(new Vector2(c.midfieldBehindForwards(), 0));
                side = new Vector2(0, 1);
            } else {
                centre = dc.plus(u.times(c.midfieldAhead()));
                side = left;
            }
            p.put(Role.ML, centre.plus(side.times(c.midfieldSpread())));
            p.put(Role.MR, centre.minus(side.times(c.midfieldSpread())));
        }

        double gy = Math.max(-(field.goalWidth() / 2 - 0.2), Math.min(field.goalWidth() / 2 - 0.2, ball.y() * 0.2));
        p.put(Role.GK, new Vector2(-hl + c.goalkeeperDepth(), gy));

        for (Map.Entry<Role, Vector2> e : p.entrySet()) e.setValue(inside(e.getValue(), hl - c.inset(), hw - c.inset()));
        return new Formation(p);
    }

    /** Reflects a point back off the lines it crosses, then clamps it inside. */
    static Vector2 inside(Vector2 q, double hx, double hy) {
        double x = q.x(), y = q.y();
        if (x > hx) x = 2 * hx - x; else if (x < -hx) x = -2 * hx - x;
        if (y > hy) y = 2 * hy - y; else if (y < -hy) y = -2 * hy - y;
        return new Vector2(Math.max(-hx, Math.min(hx, x)), Math.max(-hy, Math.min(hy, y)));
    }
}

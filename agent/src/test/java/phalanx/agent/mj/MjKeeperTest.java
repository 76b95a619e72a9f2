package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.coordination.formation.Role;
import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;
import phalanx.model.robot.T1Model;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** The T1 goalkeeper (thesis 5.13 on rcssservermj): its line, Libero in and out, what MjBehaviour does with it, by hand. */
class MjKeeperTest {
    private static final Map<String, double[]> HEAD = Map.of("q_hj1", new double[] {0, 0}, "q_hj2", new double[] {0, 0});
    private static final double[] QUAT = {1, 0, 0, 0};

    /** Polar (distance, azimuth, elevation) of the world point (gx, gy, gz) from an upright T1 at (x, y) facing +x, head straight. */
    static double[] polar(double x, double y, double gx, double gy, double gz) {
        double[] cam = T1Model.seenToWorld(QUAT, new double[] {x, y, 0.67}, 0, 0, 0, 0, 0);
        double dx = gx - cam[0], dy = gy - cam[1], dz = gz - cam[2];
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return new double[] {d, Math.toDegrees(Math.atan2(dy, dx)), Math.toDegrees(Math.asin(dz / d))};
    }

    static MjPerception.Seen seen(String name, double x, double y, double gx, double gy, double gz) {
        double[] p = polar(x, y, gx, gy, gz);
        return new MjPerception.Seen(name, p[0], p[1], p[2]);
    }

    /**
     * A left-team T1 at (x, y) facing +x (world = own frame) in mode at t, seeing the ball at (bx, by) (none when NaN) and
     * opponents' feet at the given points.
     */
    static MjPerception view(double t, String mode, double x, double y, double bx, double by, Vector2... opponents) {
        List<MjPerception.Seen> s = new ArrayList<>();
        if (!Double.isNaN(bx)) s.add(seen("B", x, y, bx, by, 0.11));
        int id = 1;
        for (Vector2 o : opponents) {
            s.add(seen("P Other " + id + " lfoot", x, y, o.x(), o.y(), 0.05));
            s.add(seen("P Other " + id + " head", x, y, o.x(), o.y(), 1.1));
            id++;
        }
        return new MjPerception(t, 100, mode, "Phalanx", "Other", 0, 0, QUAT, new double[] {x, y, 0.67}, null, null, HEAD, Map.of(), s, List.of(), 0);
    }

    @Test
    void itsGuardPointLiesOnTheSpotsLineBetweenTheGoalsCentreAndTheBall() {
        MjKeeper k = new MjKeeper(MjField.SSIM, MjKeeper.Config.DEFAULT);   // spot 1 m out: x = -26.5; at most 1.2 m aside
        Vector2 p = k.guardPoint(new Vector2(-20, 4));
        assertEquals(-26.5, p.x(), 1e-9);
        assertEquals(4 * 1.0 / 7.5, p.y(), 1e-9, "the ball 7.5 m out and 4 m aside: 0.53 m aside at 1 m out");
        assertEquals(1.2, k.guardPoint(new Vector2(-27, 5)).y(), 1e-9, "a ball level with the spot: the post's side, at most maxShift");
        assertEquals(-1.2, k.guardPoint(new Vector2(-25, -20)).y(), 1e-9, "clamped");
        assertEquals(-0.4, k.guardPoint(new Vector2(10, -15)).y(), 1e-9, "the far half: 15/37.5");
        assertEquals(new Vector2(-26.5, 0), k.guardPoint(null), "no ball: the middle");
    }

    @Test
    void itComesOutForABallInItsPenaltyAreaThatItReachesFirstAndGoesBack() {
        MjKeeper k = new MjKeeper(MjField.SSIM, MjKeeper.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(view(1, "PlayOn", -26.5, 0, -22, 2));
        assertEquals(MjKeeper.State.LIBERO, k.update(w, true), "4.9 m from a ball inside the area, no opponent seen");
        assertTrue(k.hasBall());
        w.update(view(1.04, "PlayOn", -26.5, 0, -18.0, 0));
        assertEquals(MjKeeper.State.LIBERO, k.update(w, true), "0.5 m out of the area: within the exit margin, it keeps at it");
        w.update(view(1.08, "PlayOn", -26.5, 0, -17.0, 0));
        assertEquals(MjKeeper.State.GUARD, k.update(w, true), "1.5 m out: back");
        assertFalse(k.hasBall());
        w.update(view(1.12, "PlayOn", -26.5, 0, -17.0, 0));
        w.update(view(1.16, "PlayOn", -26.5, 0, -19.0, 0));
        assertEquals(MjKeeper.State.LIBERO, k.update(w, true), "in again");
        w.update(view(4.0, "PlayOn", -19.5, 0, Double.NaN, 0));
        assertEquals(MjKeeper.State.LIBERO, k.update(w, true), "at the ball it does not see it (below the camera's view): kept 4 s");
        w.update(view(5.2, "PlayOn", -19.5, 0, Double.NaN, 0));
        assertEquals(MjKeeper.State.GUARD, k.update(w, true), "unseen for 4.04 s: back");

        MjKeeper k2 = new MjKeeper(MjField.SSIM, MjKeeper.Config.DEFAULT);
        MjWorld w2 = new MjWorld("Phalanx");
        w2.update(view(1, "PlayOn", -26.5, 0, -22, 2, new Vector2(-21, 2)));
        assertEquals(MjKeeper.State.GUARD, k2.update(w2, true), "an opponent 1 m from the ball, the keeper 4.9 m: it stays");
        w2.update(view(1.04, "PlayOn", -26.5, 0, -22, 2, new Vector2(-17, 2)));
        assertEquals(MjKeeper.State.GUARD, k2.update(w2, true), "the opponent 5.0 m off, the keeper 4.92 m: not nearer by 0.5 m");
        w2.update(view(1.06, "PlayOn", -26.5, 0, -22, 2, new Vector2(-16, 2)));
        assertEquals(MjKeeper.State.LIBERO, k2.update(w2, true), "the opponent 6 m off: out");
        w2.update(view(1.08, "PlayOn", -26.5, 0, -22, 2, new Vector2(-22.5, 2.5)));
        assertEquals(MjKeeper.State.GUARD, k2.update(w2, true), "an opponent now nearer: back");
        w2.update(view(1.12, "PlayOn", -26.5, 0, -22, 2));
        assertEquals(MjKeeper.State.GUARD, k2.update(w2, false), "we may not play the ball (their set piece, barred)");
        w2.update(view(5, "PlayOn", -26.5, 0, Double.NaN, 0));
        assertEquals(MjKeeper.State.GUARD, k2.update(w2, true), "the ball last seen 4 s ago");
    }

    @Test
    void theBehaviourSideStepsTheKeeperOntoItsLineAndKicksInLibero() {
        MjBehaviour gk = new MjBehaviour(MjField.SSIM, 1, MjBehaviour.Config.DEFAULT);
        assertEquals(Role.GK, gk.role());
        assertEquals(new phalanx.model.field.Pose2(-26.5, 0, 0), gk.kickOffSpot(), "it beams to its guard spot");
        MjWorld w = new MjWorld("Phalanx");
        w.update(view(1, "PlayOn", -26.5, 0, -10, 4));   // the guard point 0.24 m to its left
        MjBehaviour.Intent i = gk.decide(w, null, true);
        assertNull(i.kick());
        assertTrue(i.vy() > 0 && Math.abs(i.vx()) < 0.05, "a side step to its left: " + i);
        assertTrue(i.turnDegPerS() > 0, "turning toward the ball, 13.6 deg to the left: " + i);
        assertFalse(gk.keeperHasBall());
        w.update(view(1.04, "PlayOn", -26.5, 0, -22, 2));
        MjBehaviour.Intent out = gk.decide(w, null, false);
        assertTrue(gk.keeperHasBall(), "Libero: the coordinator plans in Support mode");
        assertEquals(gk.kickToGoal(w.self(), w.ball()), out, "to the ball the On Ball way");
        w.update(view(1.08, "free_kick_right", -26.5, 0, -22, 2));
        MjBehaviour.Intent keep = gk.decide(w, null, false);
        assertFalse(gk.keeperHasBall(), "their free kick: not to the ball");
        assertNotEquals(gk.kickToGoal(w.self(), w.ball()), keep);
    }

    @Test
    void inTheirFreeKickNearOurGoalTheKeeperLeavesTheCircle() {
        MjBehaviour gk = new MjBehaviour(MjField.SSIM, 1, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(view(1, "free_kick_right", -26.5, 0, -24, 3));   // 3.9 m from the ball, already where the referee drops it
        MjBehaviour.Intent i = gk.decide(w, null, false);
        // its place: (-27.2, -2.66), 6.5 m from the ball on the goal line's side (MjSetPieceTest): to its right, behind it
        assertTrue(i.vx() <= 0 && (i.turnDegPerS() < 0 || i.vy() < 0), "away from the ball, to its right: " + i);
    }
}

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.model.field.Vector2;

import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The T1 goalkeeper on the real rcssservermj (thesis 5.13, MjKeeper): our 7 T1s, no opponents. After the kick-off the
 * monitor puts the ball inside our penalty area, 5.4 m in front of the keeper's spot: with no opponent near, the keeper
 * comes out (Libero), kicks it within 60 s and, the ball gone, walks back to within 1 m of its guard point (within 60 s
 * of the kick). The field players are first put 8 m into the other half: their formation spots lie at such a ball, and
 * when they got there first one of them cleared it and the keeper, rightly, never kicked (1 clean-clone CI run of 3).
 * Traces the keeper every 2 s of game time. Skips without rcssservermj. Bounded by game time (a 10-minute hang guard
 * aside).
 */
class MjKeeperServerTest {
    @Test
    void theKeeperComesOutForABallInItsAreaKicksItAndGoesBack(@TempDir Path tmp) throws Exception {
        long began = System.nanoTime();
        try (MjServerTeam t = MjServerTeam.start(tmp, "Phalanx", 0)) {
            MjRuntime keeper = t.team.get(0);
            MjKeeper k = keeper.behaviour().keeper();
            assertNotNull(k, "player 1 is the goalkeeper");
            t.server.command("(kickOff Left)");
            t.waitFor(() -> keeper.world().playMode().equals("PlayOn") || keeper.world().time() > 20
                    && !keeper.world().playMode().startsWith("KickOff"), "play on");
            t.waitFor(() -> !keeper.world().playMode().startsWith("KickOff"), "the kick-off's end");
            for (int n = 2; n <= t.team.size(); n++) {   // 30 m and more from the ball: a minute's walk for a T1
                t.server.command(String.format(Locale.ROOT, "(agent (unum %d) (team Phalanx) (move 8 %.1f 0.67 180))", n, -9.0 + 3 * n));
            }
            t.server.command("(ball (pos -21.5 1.5 0.11))");
            double placed = keeper.world().time();
            t.waitFor(() -> k.state() == MjKeeper.State.LIBERO || keeper.world().time() - placed > 5, "the keeper's Libero");
            assertEquals(MjKeeper.State.LIBERO, k.state(), "within 5 s the keeper goes for the ball in its area");
            double out = keeper.world().time() - placed;
            double[] ball = new double[3];
            t.server.onMonitorMessage(m -> {
                double[] b = phalanx.match.MjMonitor.ball(m);
                if (b != null) System.arraycopy(b, 0, ball, 0, 3);
            });
            double[] next = {placed};
            Runnable trace = () -> {
                if (keeper.world().time() >= next[0]) {   // a trace every 2 s of game time: the keeper, its ball, the true ball
                    next[0] += 2;
                    System.out.printf(Locale.ROOT, "  %.1f s %s self %s ball %s (true %.2f, %.2f)%n", keeper.world().time() - placed, k.state(),
                            keeper.world().self(), keeper.world().ball(), ball[0], ball[1]);
                }
            };
            t.waitFor(() -> {
                trace.run();
                return keeper.kicks() > 0 || keeper.world().time() - placed > 60;
            }, "the keeper's kick");
            double kicked = keeper.world().time() - placed;
            Vector2 ballAfter = keeper.world().ball();
            // What the keeper was when the wait ended, kept: read again at the asserts it may have moved on a cycle (the ball's
            // belief moves its guard point; a ball rolling back into its area sends it out again).
            MjKeeper.State[] stateThen = {null};
            double[] offThen = {Double.NaN};
            t.waitFor(() -> {
                trace.run();
                stateThen[0] = k.state();
                offThen[0] = keeper.world().self().position().distanceTo(k.guardPoint(keeper.world().ball()));
                return stateThen[0] == MjKeeper.State.GUARD && offThen[0] < 1.0 || keeper.world().time() - placed > kicked + 60;
            }, "the keeper back on its line");
            double back = keeper.world().time() - placed;
            System.out.printf(Locale.ROOT, "MjKeeperServerTest: Libero %.2f s after the ball was put in the area, %d kick(s) by %.2f s "
                            + "(the ball then believed at %s), back on its line by %.2f s (%s, %.2f m from its guard point); %.0f s in all%n",
                    out, keeper.kicks(), kicked, ballAfter, back, keeper.world().self(), offThen[0], (System.nanoTime() - began) / 1e9);
            t.printLog();
            assertTrue(keeper.kicks() >= 1, "the keeper kicked within 60 s");
            assertEquals(MjKeeper.State.GUARD, stateThen[0]);
            assertTrue(offThen[0] < 1.0, "back on its line within 60 s of its kick: " + offThen[0] + " m off");
        }
    }
}

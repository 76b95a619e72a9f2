package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.agent.PlayerOptions;
import phalanx.match.MjMonitor;
import phalanx.match.MjServerProcess;
import phalanx.match.ServerProcess;
import phalanx.model.field.MjField;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The T1 kick in a game on the real rcssservermj: one forward alone, the kick-off given; it walks to the ball on the
 * centre spot, kicks it, and the ball (its place from the monitor's scene graph) travels at least KICK_FRACTION of
 * the kick bench's median (motion/README.md "T1 kick": the bench kicks from a settled stand, the game's kick comes
 * after an approach, with the ball off the bench's spot by up to MjBehaviour.Config.kickToleranceM), within 60 deg
 * of the goal's direction. Skips without rcssservermj. Bounded by game time, not wall time.
 */
class MjKickTest {
    /** scripts/phalanx bench t1 --trial kick --kicks 10 --foot both, 2026-12-04 (motion/README.md "T1 kick"). */
    static final double BENCH_MEDIAN_M = 11.44;
    static final double KICK_FRACTION = 0.3;

    private volatile double[] ball;

    @Test
    void theForwardWalksToTheBallAndKicksItAway(@TempDir Path tmp) throws Exception {
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        assumeTrue(exe.isPresent(), "rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
        int port = freePair(4270, 4298);
        MjServerProcess server = MjServerProcess.startReady(exe.get(), new MjServerProcess.Settings(port, port + 1, true, false), tmp,
                90_000, started -> { }, why -> System.out.println("rcssservermj started again: " + why));
        server.onMonitorMessage(m -> {
            double[] b = MjMonitor.ball(m);
            if (b != null) ball = b;
        });
        ExecutorService pool = Executors.newSingleThreadExecutor();
        try {
            MjRuntime fc = new MjRuntime("Phalanx", 7, MjField.SSIM);
            PlayerOptions o = PlayerOptions.parse("--port", String.valueOf(port), "--team", "Phalanx", "--unum", "7", "--server", "mj");
            Future<MjPlayer.Outcome> player = pool.submit(() -> MjPlayer.play(o, fc));
            waitFor(() -> fc.cycles() > 150 && ball != null, "the forward beamed and standing", player, server);
            // The ball lies still on the centre spot until the kick (a touch before it bars the kick, below): measured from
            // here, not from the ball seen when the test's poll finds the kick counted, which on a fast machine may come
            // after the swing has met the ball (the count goes up at the kick's start, the swing about 1 s later).
            double[] before = ball.clone();
            server.command("(kickOff Left)");
            long start = fc.cycles();
            waitFor(() -> fc.kicks() > 0 || fc.touchBars() > 0 || fc.cycles() > start + 3000, "a kick, a touch bar or 60 game seconds", player, server);
            // Since the set-piece rules (MjTouchRule), a push on the approach is the kick-off's one touch: alone on the
            // field, the forward may not touch the ball again (a double-touch free kick), so there is no kick to measure
            // in that run (about 2 in 3 runs in session 25's clean-clone CI). Then it must not touch again: skipped, not failed.
            if (fc.kicks() == 0 && fc.touchBars() > 0) {
                long barredAt = fc.cycles();
                waitFor(() -> fc.cycles() > barredAt + 250, "5 game seconds after the bar", player, server);
                assertEquals(0, fc.kicks(), "a barred forward does not kick");
                org.junit.jupiter.api.Assumptions.abort("the forward's approach pushed the ball (the kick-off's one touch); "
                        + "no kick allowed after it, so none measured in this run");
            }
            assertTrue(fc.kicks() > 0, "the forward kicked within 60 game seconds; it is at " + fc.world().self()
                    + ", the ball at " + fc.world().ball() + (fc.kicksRefused() > 0 ? ", kicks refused " + fc.kicksRefused() : ""));
            long kicked = fc.cycles();
            double travel = 0, dx = 0, dy = 0;
            long fell = -1;
            for (int k = 1; k <= 300; k++) {   // the ball's farthest from where it lay, over 6 game seconds after the poll saw the kick
                long until = kicked + k;
                waitFor(() -> fc.cycles() > until, "cycle " + k + " after the kick", player, server);
                double[] b = ball;
                if (Math.hypot(b[0] - before[0], b[1] - before[1]) > travel) {
                    travel = Math.hypot(b[0] - before[0], b[1] - before[1]);
                    dx = b[0] - before[0];
                    dy = b[1] - before[1];
                }
                if (fell < 0 && !fc.world().upright()) fell = fc.cycles() - kicked;
            }
            // the left team's opponent goal is at +x, world frame
            double offGoal = Math.toDegrees(Math.IEEEremainder(Math.atan2(dy, dx) - Math.atan2(-before[1], MjField.SSIM.halfLength() - before[0]), 2 * Math.PI));
            System.out.printf(Locale.ROOT, "MjKickTest: kicked %d cycles after the kick-off; ball %.2f m (bench median %.1f m), %.1f deg off the goal's direction; %s%n",
                    kicked - start, travel, BENCH_MEDIAN_M, offGoal, fell < 0 ? "stood" : "fell " + fell + " cycles after the kick started");
            assertTrue(Math.abs(offGoal) < 60, "kicked towards the opponent goal: " + offGoal + " deg off");
            assertTrue(travel >= KICK_FRACTION * BENCH_MEDIAN_M, "the kick moved the ball " + travel + " m, under "
                    + KICK_FRACTION + " x the bench's median " + BENCH_MEDIAN_M + " m");
        } finally {
            server.stop();
            pool.shutdownNow();
        }
    }

    /** An agent port P and P + 1 for the monitor, both free, P in [from, to). */
    private static int freePair(int from, int to) {
        for (int p = from; p < to; p++) if (ServerProcess.portFree(p) && ServerProcess.portFree(p + 1)) return p;
        throw new IllegalStateException("no free port pair in " + from + ".." + to);
    }

    private static void waitFor(BooleanSupplier done, String what, Future<MjPlayer.Outcome> player, MjServerProcess server) throws Exception {
        long deadline = System.nanoTime() + 600_000_000_000L;   // a guard against a hang only (10 min)
        while (!done.getAsBoolean()) {
            if (player.isDone()) fail("the player ended before " + what + ": " + player.get() + "; server log: " + Files.readString(server.log()));
            if (System.nanoTime() > deadline) fail("no " + what + " within 10 minutes");
            Thread.sleep(1);
        }
    }
}

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.agent.PlayerOptions;
import phalanx.match.MjServerProcess;
import phalanx.match.ServerProcess;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The whole team on the real rcssservermj (issue 20's CI test): 7 T1 players connect, parse every message, beam
 * to their kick-off spots (the server's ground-truth torso position within 0.1 m) and stand; after the kick-off the
 * forward (the nearest to the ball by the team's 10-byte reports) walks toward the ball, and every player has
 * heard its team-mates. Needs rcssservermj (scripts/setup.sh installs it into .venv); skips without it.
 * Bounded by game time (the server runs in sync mode, as fast as the agents answer).
 */
class MjTeamTest {
    private static final String TEAM = "Phalanx";

    @Test
    void aFullTeamConnectsBeamsAndItsForwardWalksToTheBall(@TempDir Path tmp) throws Exception {
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        assumeTrue(exe.isPresent(), "rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
        int port = ServerProcess.freePortPair(3960);
        MjServerProcess server = MjServerProcess.startReady(exe.get(), new MjServerProcess.Settings(port, port + 100, true, false), tmp,
                90_000, started -> { }, why -> System.out.println("rcssservermj started again: " + why));
        MjField field = MjField.SSIM;
        List<MjRuntime> team = new ArrayList<>();
        ExecutorService pool = Executors.newFixedThreadPool(field.players());
        try {
            List<Future<MjPlayer.Outcome>> outcomes = new ArrayList<>();
            for (int n = 1; n <= field.players(); n++) {
                MjRuntime r = new MjRuntime(TEAM, n, field);
                team.add(r);
                PlayerOptions o = PlayerOptions.parse("--port", String.valueOf(port), "--team", TEAM, "--unum", String.valueOf(n), "--server", "mj");
                outcomes.add(pool.submit(() -> MjPlayer.play(o, r)));
            }
            // every player in and on its spot, before the kick-off
            waitFor(() -> team.stream().allMatch(r -> r.cycles() > 150), "all players running 3 s", outcomes, server);
            for (MjRuntime r : team) {
                Pose2 spot = r.behaviour().kickOffSpot(), at = r.world().self();
                assertEquals(1, r.world().side(), "player " + r.unum() + " on the left");
                assertTrue(r.beams() >= 1, "player " + r.unum() + " beamed");
                assertEquals(0, at.position().distanceTo(spot.position()), 0.1, "player " + r.unum() + " at " + at + ", spot " + spot);
                assertTrue(r.world().upright(), "player " + r.unum() + " standing after its beam");
            }
            MjRuntime forward = team.get(field.players() - 1);
            Vector2 ball = forward.world().ball();
            assertNotNull(ball, "the forward sees the ball from its spot");
            double before = forward.world().self().position().distanceTo(ball);
            long start = forward.cycles();
            server.command("(kickOff Left)");
            double closest = before;
            for (int k = 1; k <= 10; k++) {   // the closest approach, sampled each game second
                long until = start + 50L * k;
                waitFor(() -> forward.cycles() > until, "game second " + k + " after the kick-off", outcomes, server);
                closest = Math.min(closest, forward.world().self().position().distanceTo(forward.world().ball()));
            }
            String mode = forward.world().playMode();
            // the kick-off was given (walking into the ball twice gives the other side a free kick: double touch)
            assertNotEquals("BeforeKickOff", mode, "kick-off given");
            double after = closest;
            assertTrue(before - after > 0.5, "the forward walked toward the ball: " + before + " m -> " + after + " m");
            for (MjRuntime r : team) {
                assertEquals(0, r.malformed(), "player " + r.unum() + " parsed every message");
                assertTrue(r.heardFromMates() > 0, "player " + r.unum() + " heard its team-mates' reports");
            }
            System.out.printf("MjTeamTest: 7 players beamed; forward %.2f m from the ball, %.2f m at the closest, in %d cycles%n",
                    before, after, forward.cycles() - start);
        } finally {
            server.stop();
            pool.shutdownNow();
        }
    }

    private static void waitFor(BooleanSupplier done, String what, List<Future<MjPlayer.Outcome>> players,
                                MjServerProcess server) throws Exception {
        // a guard against a hang only (10 min), not a speed figure
        long deadline = System.nanoTime() + 600_000_000_000L;
        while (!done.getAsBoolean()) {
            for (Future<MjPlayer.Outcome> f : players) {
                if (f.isDone()) fail("a player ended before " + what + ": " + f.get() + "; server log: " + read(server.log()));
            }
            if (System.nanoTime() > deadline) fail("no " + what + " within 10 minutes; server log: " + read(server.log()));
            Thread.sleep(50);
        }
    }

    private static String read(Path log) {
        try {
            return Files.exists(log) ? Files.readString(log) : "(no log)";
        } catch (Exception e) {
            return "(unreadable: " + e + ")";
        }
    }
}

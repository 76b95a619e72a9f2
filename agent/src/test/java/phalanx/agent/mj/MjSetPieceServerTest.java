package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The set-piece rules on the real rcssservermj (soccer_referee.py, docs/rcssservermj.md "Set pieces"): our 7 T1s, no
 * opponents, one server run. (1) Our kick-off: the taker's touch ends it, and no double-touch free kick follows (the
 * whole test long: the monitor's play modes).
 * (2) Their kick-in: after one of ours has kicked, the monitor puts the ball over the touch line where it lands on the
 * line at least 7 m from every one of ours (so nobody stands inside the circle when it is called), one of them placed
 * beforehand 7.1 m from it with its formation spot inside the circle, and for the kick-in's 15 s nobody of ours walks
 * within the 5.5 m the referee drops players for. (3) Their kick-off: the ball put into their
 * goal (Goal_Left), our players beam for the other side's kick-off and for its 15 s none stands in their half or the
 * centre circle.
 * A drop by the referee shows as a player's torso jumping more than 1.5 m between two looks (every 20 ms of wall time,
 * under a cycle). Prints its figures (the margin kept) before it asserts, so a run of an older build still measures.
 */
class MjSetPieceServerTest {
    private static final double CIRCLE = 5.5, JUMP_M = 1.5, AT_START_S = 0.1;

    /** What one watched stretch of game time showed. */
    static final class Watch {
        final Set<Integer> droppedAtStart = new HashSet<>();
        int drops;
        double closest = Double.POSITIVE_INFINITY;
        int closestPlayer;
        boolean modeSeen;
        final Set<String> modes = new HashSet<>();
    }

    @Test
    void ourPlayersKeepTheSetPieceRules(@TempDir Path tmp) throws Exception {
        long began = System.nanoTime();
        try (MjServerTeam t = MjServerTeam.start(tmp, "Phalanx", 0)) {
            MjRuntime clock = t.team.get(0);
            // every play mode the monitor shows, the whole test long: free_kick_right is only given for our double touch
            Set<String> modes = java.util.concurrent.ConcurrentHashMap.newKeySet();
            phalanx.match.MjMonitor monitor = new phalanx.match.MjMonitor();
            t.server.onMonitorMessage(m -> {
                phalanx.match.MjMonitor.State st = monitor.accept(m);
                if (st != null && modes.add(st.playMode()) && st.playMode().equals("free_kick_right")) {
                    for (MjRuntime r : t.team) System.out.printf(Locale.ROOT, "  free_kick_right at %.2f s: player %d at %s%s, the ball believed at %s%n",
                            st.time(), r.unum(), r.world().self(), r.barred() ? " (barred)" : "", r.world().ball());
                }
            });
            // (1) our kick-off: until it turns PlayOn (a touch, or 15 s), then 6 s more
            t.server.command("(kickOff Left)");
            t.waitFor(() -> clock.world().playMode().startsWith("KickOff"), "the kick-off");
            double kickOff = clock.world().time();
            t.waitFor(() -> !clock.world().playMode().startsWith("KickOff"), "the end of the kick-off");
            double touched = clock.world().time() - kickOff;
            Watch afterKickOff = watch(t, clock, 6, null, "");

            // (2) their kick-in: once one of ours has kicked (the ball's last contact is ours), out over the touch line
            t.waitFor(() -> t.team.stream().anyMatch(r -> r.kicks() > 0) || clock.world().time() - kickOff > 40, "a kick of ours");
            // player 5 (ML) first 3 m in from the line, 7.1 m from where the ball will lie: its formation spot for that ball
            // is 3.2 m from it (the stretched formation), so it wants to walk into the circle
            MjRuntime ml = t.team.get(4);
            Vector2 line = touchLinePoint(t.team.stream().filter(r -> r != ml).toList(), 7.0);
            t.server.command(String.format(Locale.ROOT, "(agent (unum 5) (team Phalanx) (move %.2f 11.5 0.67 90))", line.x() - 3));
            double placed = clock.world().time();
            t.waitFor(() -> clock.world().time() - placed > 1.5, "player 5 placed");
            t.server.command(String.format(Locale.ROOT, "(ball (pos %.2f %.2f 0.11))", line.x(), 18.6));
            t.waitFor(() -> !clock.world().playMode().equals("PlayOn") || clock.world().time() - kickOff > 60, "a play mode after the ball went out");
            String kickIn = clock.world().playMode();
            Watch theirKickIn = watch(t, clock, 15, line, "KickIn_Right");

            // (3) their kick-off: a goal of ours first (after the kick-in the referee lets the left team score)
            t.waitFor(() -> clock.world().playMode().equals("PlayOn"), "play on after the kick-in");
            t.server.command("(ball (pos 28.0 0 0.3))");
            t.waitFor(() -> clock.world().playMode().equals("KickOff_Right"), "their kick-off after our goal");
            Watch theirKickOff = watch(t, clock, 14.5, Vector2.ZERO, "KickOff_Right");
            int doubleTouch = modes.contains("free_kick_right") || afterKickOff.modes.contains("free_kick_right") ? 1 : 0;
            int inTheirHalfOrCircle = 0;
            for (MjRuntime r : t.team) {
                Vector2 p = r.world().self().position();
                if (p.x() > 0 || p.norm() < CIRCLE) inTheirHalfOrCircle++;
            }

            System.out.printf(Locale.ROOT, "MjSetPieceServerTest: our kick-off touched after %.2f s, a double-touch free kick %d;"
                            + " their %s at (%.2f, 18): %d dropped at its start, %d dropped later, closest %.2f m (player %d);"
                            + " their kick-off: %d dropped at its start, %d later, closest to the centre %.2f m (player %d), %d standing in"
                            + " their half or the circle at its end; %.0f s in all%n",
                    touched, doubleTouch, kickIn, line.x(), theirKickIn.droppedAtStart.size(), theirKickIn.drops, theirKickIn.closest,
                    theirKickIn.closestPlayer, theirKickOff.droppedAtStart.size(), theirKickOff.drops, theirKickOff.closest,
                    theirKickOff.closestPlayer, inTheirHalfOrCircle, (System.nanoTime() - began) / 1e9);
            t.printLog();
            assertTrue(touched < 14.9, "our kick-off taker touched the ball (" + touched + " s)");
            assertEquals(0, doubleTouch, "no double-touch free kick, the whole test long");
            assertEquals("KickIn_Right", kickIn, "the ball out over the touch line, last touched by us");
            assertTrue(theirKickIn.modeSeen);
            assertEquals(0, theirKickIn.drops, "nobody of ours walked into the circle in their kick-in");
            assertTrue(theirKickIn.closest >= CIRCLE, "closest " + theirKickIn.closest);
            assertTrue(theirKickOff.modeSeen);
            assertEquals(0, theirKickOff.droppedAtStart.size() + theirKickOff.drops, "nobody of ours dropped at their kick-off");
            assertEquals(0, inTheirHalfOrCircle);
        }
    }

    /**
     * Watches {@code seconds} of game time (player 1's clock): drops (torso jumps, beams aside) and, while {@code mode}
     * is on, the closest any player came to {@code ball} (those dropped at the mode's start left out).
     */
    private static Watch watch(MjServerTeam t, MjRuntime clock, double seconds, Vector2 ball, String mode) throws Exception {
        Watch w = new Watch();
        Map<Integer, Pose2> last = new HashMap<>();
        double start = clock.world().time(), modeStart = Double.NaN;
        while (clock.world().time() - start < seconds) {
            String now = clock.world().playMode();
            if (w.modes.add(now) && now.startsWith("free_kick")) {
                for (MjRuntime r : t.team) System.out.printf(Locale.ROOT, "  %s at %.2f s: player %d at %s, the ball believed at %s%n", now,
                        clock.world().time(), r.unum(), r.world().self(), r.world().ball());
            }
            boolean in = now.equals(mode);
            if (in && Double.isNaN(modeStart)) modeStart = clock.world().time();
            if (in) w.modeSeen = true;
            for (MjRuntime r : t.team) {
                Pose2 p = r.world().self(), before = last.put(r.unum(), p);
                if (p == null || before == null || r.world().beamAllowed()) continue;
                if (before.position().distanceTo(p.position()) > JUMP_M) {
                    if (in && clock.world().time() - modeStart <= AT_START_S) w.droppedAtStart.add(r.unum());
                    else if (in) w.drops++;
                } else if (in && ball != null && !w.droppedAtStart.contains(r.unum())) {
                    double d = p.position().distanceTo(ball);
                    if (d < w.closest) { w.closest = d; w.closestPlayer = r.unum(); }
                }
            }
            for (var f : t.outcomes) if (f.isDone()) fail("a player ended: " + f.get());
            Thread.sleep(20);
        }
        return w;
    }

    /** The point of the upper touch line (y = 18) nearest our players that is at least {@code clear} from each of them. */
    private static Vector2 touchLinePoint(List<MjRuntime> team, double clear) {
        Vector2 best = new Vector2(0, 18);
        double bestD = Double.POSITIVE_INFINITY;
        for (double x = -22; x <= 22; x += 0.5) {
            Vector2 p = new Vector2(x, 18);
            double d = Double.POSITIVE_INFINITY;
            for (MjRuntime r : team) d = Math.min(d, r.world().self().position().distanceTo(p));
            if (d >= clear && d < bestD) { bestD = d; best = p; }
        }
        return best;
    }
}

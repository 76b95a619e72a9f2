package phalanx.agent;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/**
 * start.sh and stop.sh refuse bad input with a clear message, before building or starting anything;
 * scripts/phalanx stats player reads a log folder.
 */
class ScriptsTest {

    private record Run(int status, String output) {}

    private static Run run(String... command) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "script did not finish: " + List.of(command));
        return new Run(p.exitValue(), new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    @Test
    void startRefusesUnknownOptionsAndBadPorts() throws Exception {
        Run r = run("bash", "scripts/start.sh", "--bogus");
        assertEquals(2, r.status());
        assertTrue(r.output().contains("unknown option --bogus"), r.output());
        r = run("bash", "scripts/start.sh", "127.0.0.1", "port");
        assertEquals(2, r.status());
        assertTrue(r.output().contains("port must be a number"), r.output());
    }

    @Test
    void playRefusesBadArgumentsBeforeStartingAnything() throws Exception {
        Run r = run("bash", "scripts/play.sh", "--bogus");
        assertEquals(2, r.status());
        assertTrue(r.output().contains("unknown argument --bogus"), r.output());
        r = run("bash", "scripts/play.sh", "--server", "webots");
        assertEquals(2, r.status());
        assertTrue(r.output().contains("--server must be auto, simspark or mj, got 'webots'"), r.output());
        r = run("bash", "scripts/play.sh", "--halves", "3");
        assertEquals(2, r.status());
        assertTrue(r.output().contains("--halves must be 1 or 2"), r.output());
    }

    @Test
    void startWithMjSaysHowToGetRcssservermjWhenNoneListens() throws Exception {
        Run r = run("bash", "scripts/start.sh", "127.0.0.1", String.valueOf(freePort()), "--mj");
        assertEquals(3, r.status());
        assertTrue(r.output().contains("no rcssservermj is listening") && r.output().contains(".venv/bin/rcssservermj"), r.output());
    }

    @Test
    void startSaysHowToGetTheServerWhenNoneListens() throws Exception {
        Run r = run("bash", "scripts/start.sh", "127.0.0.1", String.valueOf(freePort()));
        assertEquals(3, r.status());
        assertTrue(r.output().contains("no rcssserver3d is listening"), r.output());
        assertTrue(r.output().contains("build it from a SimSpark release"), r.output());
    }

    @Test
    void stopRefusesAFolderWithoutPidsAndStopsNothingElse() throws Exception {
        Path dir = Files.createTempDirectory("phalanx-stop");
        Run r = run("bash", "scripts/stop.sh", dir.toString());
        assertEquals(1, r.status());
        assertTrue(r.output().contains("no pids file"), r.output());
        // A PID that is not one of our players (this JVM's parent shell, say) is left alone.
        Files.writeString(dir.resolve("pids"), ProcessHandle.current().pid() + "\n");
        r = run("bash", "scripts/stop.sh", dir.toString());
        assertEquals(0, r.status());
        assertTrue(r.output().contains("stopped 0 player(s)"), r.output());
    }

    /**
     * scripts/phalanx stats player on a log folder written by hand: think times (wall, and CPU where the
     * log has it: player 2's older line has none), GC pauses, falls and the time lying.
     */
    @Test
    void playerStatsCountsThinkTimesGcPausesAndFalls() throws Exception {
        Path dir = Files.createTempDirectory("player-stats");
        Files.writeString(dir.resolve("player-1.out"), String.join("\n",
                "INFO: think_us p50=100 p99=900 max=2500 cycles=3000 over_20ms=0 cpu_p50=30 cpu_p99=200 cpu_max=700",
                "INFO: fall 1: FALLEN_BACK at game time 10.00",
                "INFO: fall 1: standing again at game time 13.00 after 3.00 s",
                "INFO: fall 2: FALLEN_FRONT at game time 50.00", ""));
        Files.writeString(dir.resolve("player-2.out"), String.join("\n",
                "INFO: think_us p50=120 p99=1500 max=30000 cycles=3000 over_20ms=3",
                "INFO: fall 1: FALLEN_FRONT at game time 20.00",
                "INFO: fall 1: standing again at game time 22.00 after 2.00 s",
                "INFO: fall 2: FALLEN_FRONT at game time 40.00",
                "INFO: fall 2: standing again at game time 46.00 after 6.00 s", ""));
        Files.writeString(dir.resolve("gc-1.log"), "[1.0s][info] GC(0) Pause Young (Allocation Failure) 11M->2M(30M) 0.629ms\n");
        Files.writeString(dir.resolve("gc-2.log"), "[1.0s][info] GC(0) Pause Young (Allocation Failure) 11M->2M(30M) 7.5ms\n"
                + "[2.0s][info] GC(1) Pause Young (Allocation Failure) 11M->2M(30M) 1.0ms\n");
        Run r = run("bash", "scripts/phalanx", "stats", "player", dir.toString());
        assertEquals(0, r.status(), r.output());
        String last = r.output().strip().lines().reduce((a, b) -> b).orElse("");
        assertEquals("think_p50_us_max=120 think_p99_us_max=1500 think_max_us=30000 cycles=6000 over_20ms=3 over_20ms_share=0.0005"
                + " gc_pauses=3 gc_max_ms=7.5 falls=4 stood_up=3 down_s_median=3.00 cpu_p50_us_max=30 cpu_p99_us_max=200 cpu_max_us=700", last);
        assertTrue(r.output().lines().anyMatch(l -> l.matches("2 .* - +- +-")), "player 2 logged no CPU time: " + r.output());
        // no player with CPU figures: NaN, not 0
        Files.writeString(dir.resolve("player-1.out"), "INFO: think_us p50=100 p99=900 max=2500 cycles=3000 over_20ms=0\n");
        r = run("bash", "scripts/phalanx", "stats", "player", dir.toString());
        assertTrue(r.output().strip().endsWith("cpu_p50_us_max=NaN cpu_p99_us_max=NaN cpu_max_us=NaN"), r.output());
    }
}

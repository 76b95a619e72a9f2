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

/** start.sh and stop.sh refuse bad input with a clear message, before building or starting anything. */
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
}

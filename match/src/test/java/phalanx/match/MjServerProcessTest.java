package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

class MjServerProcessTest {
    private static Path executable(Path dir, String name) throws IOException {
        Files.createDirectories(dir);
        Path f = dir.resolve(name);
        Files.writeString(f, "#!/bin/sh\n");
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rwxr-xr-x"));
        return f;
    }

    @Test
    void findsTheVariableThenTheProjectVenvThenPath(@TempDir Path tmp) throws IOException {
        Path root = tmp.resolve("project");
        Path onPath = executable(tmp.resolve("bin"), "rcssservermj");
        Map<String, String> env = Map.of("PATH", "/nonexistent:" + tmp.resolve("bin"));
        assertEquals(Optional.of(onPath), MjServerProcess.find(env, root), "PATH when there is no venv");
        Path venv = executable(root.resolve(".venv/bin"), "rcssservermj");
        assertEquals(Optional.of(venv), MjServerProcess.find(env, root), "the project's venv before PATH");
        Path own = executable(tmp.resolve("own"), "server");
        assertEquals(Optional.of(own), MjServerProcess.find(Map.of("PATH", env.get("PATH"), "PHALANX_RCSSSERVERMJ", own.toString()), root));
        assertEquals(Optional.empty(), MjServerProcess.find(Map.of("PHALANX_RCSSSERVERMJ", tmp.resolve("missing").toString(), "PATH", env.get("PATH")), root),
                "a variable naming no executable is not silently replaced by another server");
        assertEquals(Optional.empty(), MjServerProcess.find(Map.of(), tmp.resolve("elsewhere")));
    }

    @Test
    void commandIsLocalHeadlessAndSync() {
        List<String> argv = MjServerProcess.command(Path.of("/x/rcssservermj"), new MjServerProcess.Settings(3950, 4050, true, false));
        assertEquals(List.of("/x/rcssservermj", "--host", "127.0.0.1", "--aport", "3950", "--mport", "4050", "--no-render",
                "--sync", "--no-realtime"), argv);
        assertEquals(List.of("/x/rcssservermj", "--host", "127.0.0.1", "--aport", "3950", "--mport", "4050", "--no-render",
                "--sync", "--no-realtime", "--phase", "1", "--time", "540.0"),
                MjServerProcess.command(Path.of("/x/rcssservermj"), new MjServerProcess.Settings(3950, 4050, true, false, 1, 540)),
                "the second half, 60 s long");
        assertThrows(IllegalArgumentException.class, () -> new MjServerProcess.Settings(3950, 4050, true, false, 2, 0));
        assertThrows(IllegalArgumentException.class, () -> new MjServerProcess.Settings(3950, 4050, false, false));
        assertThrows(IllegalArgumentException.class, () -> new MjServerProcess.Settings(3950, 3950, true, true));
    }

    @Test
    void simulationTimeOfARecordedMonitorMessage() throws IOException {
        String first = Files.readAllLines(Path.of("match/src/test/resources/rcssservermj/monitor-kickoff.txt")).get(0);
        assertTrue(MjServerProcess.simulationTime(first) > 0, first.substring(0, 40));
        assertEquals(-1, MjServerProcess.simulationTime("((RSMP 1 0)((gt 1 0)x))"));
        assertEquals(-1, MjServerProcess.simulationTime("((RSMP 1 0)"));
    }

    @Test
    void aServerThatExitsAtOnceIsStartedOnceMoreThenRefusedWithBothReasonsAndItsOutput(@TempDir Path tmp) throws Exception {
        Path exe = tmp.resolve("dies");
        Files.writeString(exe, "#!/bin/sh\necho \"Traceback: no MuJoCo here\"\nexit 7\n");
        Files.setPosixFilePermissions(exe, PosixFilePermissions.fromString("rwxr-xr-x"));
        List<String> retries = new java.util.ArrayList<>();
        List<MjServerProcess> started = new java.util.ArrayList<>();
        int port = ServerProcess.freePortPair(3950);
        IOException e = assertThrows(IOException.class, () -> MjServerProcess.startReady(exe,
                new MjServerProcess.Settings(port, port + 100, true, false), tmp.resolve("run"), 20_000, started::add, retries::add));
        assertEquals(2, started.size(), "started twice");
        assertEquals(1, retries.size(), retries.toString());
        assertTrue(retries.get(0).contains("exited before 'Starting server... DONE!' (exit 7)") && retries.get(0).contains("no MuJoCo here"),
                retries.get(0));
        assertTrue(e.getMessage().contains("twice") && e.getMessage().contains("(exit 7)") && e.getMessage().contains("no MuJoCo here"),
                e.getMessage());
        assertTrue(Files.exists(tmp.resolve("run/retry/server.log")), "the second start has its own folder");
        for (MjServerProcess p : started) assertFalse(p.alive());
    }

    /** Needs the real rcssservermj (scripts/setup.sh installs it into .venv); skips with a message without it. */
    @Test
    void realServerAcceptsAT1AndSendsItsPerceptionsEachCycle(@TempDir Path tmp) throws Exception {
        Optional<Path> exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir")));
        assumeTrue(exe.isPresent(), "rcssservermj not found ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh");
        int port = ServerProcess.freePortPair(3950);
        // importing MuJoCo and compiling the world takes seconds on a first start
        MjServerProcess server = MjServerProcess.startReady(exe.get(), new MjServerProcess.Settings(port, port + 100, true, false), tmp,
                90_000, started -> { }, why -> System.out.println("rcssservermj started again: " + why));
        try (Socket s = connect(port, server)) {
            s.setSoTimeout(20_000);
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(s.getInputStream());
            send(out, "(init T1 Phalanx 1)");
            double last = -1;
            for (int i = 0; i < 5; i++) {
                String msg;
                try {
                    msg = receive(in);
                } catch (IOException e) {
                    throw new AssertionError("no perception " + i + " (" + e + "); server log: " + read(server.log()), e);
                }
                assertTrue(msg.contains("(GS ") && msg.contains("(HJ (n q_llj4)") && msg.contains("(pos (n torso_pos)"), msg);
                int at = msg.indexOf("(time (now ") + 11;
                double now = Double.parseDouble(msg.substring(at, msg.indexOf(')', at)));
                if (last >= 0) assertEquals(0.02, now - last, 1e-6, "one message per 0.02 s cycle");
                last = now;
                send(out, "(syn)");
            }
        } finally {
            server.stop();
        }
        assertFalse(server.alive(), "stopped by PID");
    }

    private static Socket connect(int port, MjServerProcess server) throws Exception {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (true) {
            try {
                return new Socket("127.0.0.1", port);
            } catch (IOException e) {
                if (!server.alive()) fail("rcssservermj exited: " + Files.readString(server.log()));
                if (System.nanoTime() > deadline) throw e;
                Thread.sleep(200);
            }
        }
    }

    private static String read(Path log) {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return "(unreadable: " + e + ")";
        }
    }

    private static void send(DataOutputStream out, String msg) throws IOException {
        byte[] b = msg.getBytes(StandardCharsets.US_ASCII);
        out.writeInt(b.length);
        out.write(b);
        out.flush();
    }

    private static String receive(DataInputStream in) throws IOException {
        byte[] b = new byte[in.readInt()];
        in.readFully(b);
        return new String(b, StandardCharsets.US_ASCII);
    }
}

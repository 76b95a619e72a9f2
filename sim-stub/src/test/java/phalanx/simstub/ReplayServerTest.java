package phalanx.simstub;

import org.junit.jupiter.api.Test;
import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.ServerConnection;

import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/** The stub against a raw client that speaks the framing by hand. */
class ReplayServerTest {
    private static final List<String> LINES = List.of("(time (now 0.52))", "(time (now 0.54))", "(time (now 0.56))");

    @Test
    void lockStepReplayReleasesOneLinePerReplyAndRecordsEverything() throws Exception {
        try (ReplayServer stub = new ReplayServer(LINES, 0, ReplayServer.Options.defaults()).start();
             ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000)) {
            c.send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
            c.reader().next();
            assertEquals("(time (now 0.52))", c.reader().text());
            c.send("(init (unum 1)(teamname T))(syn)");
            c.reader().next();
            assertEquals("(time (now 0.54))", c.reader().text());
            c.send("(beam -5 2 0)(syn)");
            c.reader().next();
            c.send("(he1 0.5)");
            assertThrows(ConnectionClosedException.class, () -> c.reader().next(), "stub closes after the last reply");
            ReplayServer.Result r = stub.await(5, TimeUnit.SECONDS);
            assertNull(r.error());
            assertEquals(3, r.linesSent());
            assertTrue(r.handshakeOk());
            assertEquals(List.of("(scene rsg/agent/nao/nao_hetero.rsg 0)", "(init (unum 1)(teamname T))(syn)",
                    "(beam -5 2 0)(syn)", "(he1 0.5)"), r.received());
            assertEquals(1, r.repliesWithoutSyn());
        }
    }

    @Test
    void aPlayerThatSkipsSceneIsRefusedWithTheReason() throws Exception {
        try (ReplayServer stub = new ReplayServer(LINES, 0, ReplayServer.Options.defaults()).start();
             ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000)) {
            c.send("(init (unum 1)(teamname T))");
            ReplayServer.Result r = stub.await(5, TimeUnit.SECONDS);
            assertTrue(r.error().contains("expected (scene ...) first"), r.error());
            assertFalse(r.handshakeOk());
        }
    }

    @Test
    void aPlayerThatLeavesEarlyIsReported() throws Exception {
        try (ReplayServer stub = new ReplayServer(LINES, 0, ReplayServer.Options.defaults()).start()) {
            try (ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000)) {
                c.send("(scene rsg/agent/nao/nao.rsg)");
                c.reader().next();
            }
            ReplayServer.Result r = stub.await(5, TimeUnit.SECONDS);
            assertTrue(r.error().contains("player closed the connection after 1 lines"), r.error());
        }
    }

    @Test
    void replacedLinesGoOutInsteadOfTheRecordedOnes() throws Exception {
        ReplayServer.Options o = ReplayServer.Options.defaults().withReplace(Map.of(2, "(broken"));
        try (ReplayServer stub = new ReplayServer(LINES, 0, o).start();
             ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000)) {
            c.send("(scene rsg/agent/nao/nao.rsg)");
            c.reader().next();
            c.send("(init (unum 1)(teamname T))(syn)");
            c.reader().next();
            assertEquals("(broken", c.reader().text());
        }
    }

    @Test
    void pacedModeSendsWithoutWaitingForReplies() throws Exception {
        ReplayServer.Options o = ReplayServer.Options.defaults().withPaced(true);
        try (ReplayServer stub = new ReplayServer(LINES, 0, o).start();
             ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000)) {
            c.send("(scene rsg/agent/nao/nao.rsg)");
            for (String expected : LINES) {
                c.reader().next();
                assertEquals(expected, c.reader().text());
            }
        }
    }

    @Test
    void commandLineRefusesBadArguments() throws Exception {
        assertEquals(2, Main.run(new String[]{}));
        assertEquals(2, Main.run(new String[]{"x", "--port", "abc"}));
        assertEquals(2, Main.run(new String[]{"x", "--bogus"}));
        assertEquals(2, Main.run(new String[]{"/nonexistent/recording"}));
    }
}

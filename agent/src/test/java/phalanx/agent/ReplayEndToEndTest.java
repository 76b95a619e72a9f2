package phalanx.agent;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import phalanx.comm.recording.Recordings;
import phalanx.comm.wire.ServerConnection;
import phalanx.simstub.ReplayServer;

import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The minimal player against sim-stub over a real loopback socket, replaying the recorded S1
 * stream (needs ../shared/recordings; skipped with a message when missing).
 */
class ReplayEndToEndTest {
    private static List<String> s1;

    @BeforeAll
    static void load() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        s1 = Recordings.perceptorMessages(Recordings.named("S1"));
    }

    private static ReplayServer.Result play(ReplayServer.Options options, PlayerOptions po) throws Exception {
        try (ReplayServer stub = new ReplayServer(s1, 0, options).start();
             ServerConnection c = ServerConnection.connect("127.0.0.1", stub.port(), 2000, ThinkLoop.hello(po))) {
            ThinkLoop.Outcome outcome = new ThinkLoop(c, po, new PlayerRuntime(po, Player.parts(po))).run();
            ReplayServer.Result r = stub.await(30, TimeUnit.SECONDS);
            assertEquals(s1.size(), outcome.cycles(), "the player saw every replayed message");
            return r;
        }
    }

    @Test
    void handshakeBeamAndOneSynPerCycle() throws Exception {
        ReplayServer.Result r = play(ReplayServer.Options.defaults(), PlayerOptions.parse("--unum", "1", "--team", "Phalanx"));
        assertNull(r.error());
        assertEquals(s1.size(), r.linesSent());
        assertEquals(s1.size() + 1, r.received().size(), "scene plus one reply per perceptor line");
        assertEquals("(scene rsg/agent/nao/nao_hetero.rsg 0)(syn)", r.received().get(0));
        assertEquals("(init (unum 1)(teamname Phalanx))(syn)", r.received().get(1));
        // S1 is BeforeKickOff throughout (20 s): a beam to player 1's kick-off spot as the reply to line 2,
        // repeated every 2 s while the mode lasts.
        assertTrue(r.received().get(2).startsWith("(beam -14.5 0 0)"), r.received().get(2)); // GK of the kick-off formation
        long beams = r.received().stream().filter(m -> m.contains("(beam")).count();
        assertEquals(10, beams);
        assertEquals(0, r.repliesWithoutSyn());
        // Every reply after init drives the head (he1 he2) and is well formed for the server.
        for (int i = 2; i < r.received().size(); i++) {
            String m = r.received().get(i);
            assertTrue(m.contains("(he1 ") && m.endsWith("(syn)"), "reply " + i + ": " + m);
        }
    }

    @Test
    void corruptedAndTruncatedMessagesAreSkippedAndStillAnswered() throws Exception {
        ReplayServer.Options o = ReplayServer.Options.defaults().withReplace(Map.of(
                10, "(time (now 0.70))(GS (t 0.00) (pm BeforeKickOff)",   // truncated
                11, "garbage \u0001\u0002 ((((",
                12, ""));
        ReplayServer.Result r = play(o, PlayerOptions.parse("--unum", "3"));
        assertNull(r.error());
        assertEquals(s1.size() + 1, r.received().size());
        assertEquals("(syn)", r.received().get(10), "the reply to a truncated message is a bare syn");
        assertEquals("(syn)", r.received().get(11));
        assertEquals("(syn)", r.received().get(12));
    }
}

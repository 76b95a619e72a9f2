package phalanx.agent;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class PlayerOptionsTest {

    @Test
    void defaultsAndFlags() {
        PlayerOptions d = PlayerOptions.parse();
        assertEquals("127.0.0.1", d.host());
        assertEquals(3100, d.port());
        assertEquals(11, d.players());
        assertEquals(8, d.dribbleWithin(), "dribble within 8 m of the goal (docs/matches.md, session 10)");
        assertEquals(0.0, PlayerConfig.of(PlayerOptions.parse("--dribble-within", "0")).agent().kick().dribbleWithin(), "the thesis");
        assertEquals(100.0, PlayerConfig.of(PlayerOptions.parse("--dribble-within", "100")).agent().kick().dribbleWithin());
        PlayerOptions o = PlayerOptions.parse("--host", "localhost", "--port", "3300", "--team", "Kouretes",
                "--unum", "7", "--players", "9", "--type", "4", "--log-dir", "/tmp/x");
        assertEquals(3300, o.port());
        assertEquals(7, o.unum());
        assertEquals(9, o.players());
        assertEquals(4, o.robotType());
        assertEquals("/tmp/x", o.logDir().toString());
        assertFalse(d.mj(), "SimSpark by default");
        assertTrue(PlayerOptions.parse("--server", "mj").mj());
        assertTrue(PlayerConfig.of(d).agent().approach().enabled(), "the omnidirectional approach by default");
        assertFalse(PlayerConfig.of(PlayerOptions.parse("--approach", "thesis")).agent().approach().enabled(), "4.6.2's Walk To Ball");
        assertFalse(PlayerConfig.of(d).agent().kickOff().enabled(), "the kick-off kick by default (docs/matches.md, sessions 12-13)");
        assertTrue(PlayerConfig.of(PlayerOptions.parse("--kick-off", "tap")).agent().kickOff().enabled(), "the tap");
        assertEquals(0.4, PlayerConfig.of(PlayerOptions.parse("--stand-after", "400")).motion().standAfterSeconds(), 1e-12);
        assertEquals(20, PlayerConfig.of(PlayerOptions.parse("--stand-after", "400")).motion().standAfterCycles());
        assertEquals(15, PlayerConfig.of(PlayerOptions.parse("--stand-before", "300")).motion().standBeforeCycles());
    }

    @Test
    void everyBadFlagIsNamed() {
        assertBad("--port needs a whole number, got 'x'", "--port", "x");
        assertBad("--port must be 1-65535, got 0", "--port", "0");
        assertBad("--unum must be 0-11, got 12", "--unum", "12");
        assertBad("--players must be 9 or 11, got 10", "--players", "10");
        assertBad("--type must be 0-4, got 5", "--type", "5");
        assertBad("--dribble-within must be 0-100, got 101", "--dribble-within", "101");
        assertBad("--team must be", "--team", "two words");
        assertBad("--server must be simspark or mj, got 'mujoco'", "--server", "mujoco");
        assertBad("--approach must be omni or thesis, got 'fast'", "--approach", "fast");
        assertBad("--kick-off must be tap or kick, got 'shoot'", "--kick-off", "shoot");
        assertBad("--stand-after must be 0-2000, got 2500", "--stand-after", "2500");
        assertBad("--stand-before needs a whole number, got '0.5'", "--stand-before", "0.5");
        assertBad("unknown flag --speed", "--speed", "3");
        assertBad("--host needs a value", "--host");
        assertBad("unexpected argument 'foo'", "foo");
        assertBad("--unum 10 is more than --players 9", "--players", "9", "--unum", "10");
    }

    @Test
    void playerExitsWithStatus2OnABadFlagAnd3WhenNoServerAnswers() {
        assertEquals(2, Player.run(new String[]{"--type", "9"}));
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        assertEquals(3, Player.run(new String[]{"--port", String.valueOf(port), "--connect-timeout", "0"}));
    }

    private static void assertBad(String expected, String... args) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PlayerOptions.parse(args));
        assertTrue(e.getMessage().contains(expected), "'" + e.getMessage() + "' should contain '" + expected + "'");
    }
}

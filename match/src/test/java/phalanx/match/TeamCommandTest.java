package phalanx.match;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class TeamCommandTest {

    @Test
    void expandsHostPortAndDir() {
        TeamCommand c = TeamCommand.parse("Phalanx=scripts/start.sh {host} {port} Phalanx --log-dir {dir}");
        assertEquals("Phalanx", c.label());
        assertEquals("scripts/start.sh 127.0.0.1 3500 Phalanx --log-dir /tmp/x", c.expand("127.0.0.1", 3500, "/tmp/x"));
        // '=' inside the command stays in the command
        assertEquals("A", TeamCommand.parse("A=run --x=1 {port}").label());
        assertEquals("run --x=1 3100", TeamCommand.parse("A=run --x=1 {port}").expand("h", 3100, "d"));
    }

    @Test
    void aCommandWithoutPortIsRefusedWithAReason() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TeamCommand.parse("UTA=./start.sh {host}"));
        assertTrue(e.getMessage().contains("no {port} placeholder"), e.getMessage());
    }

    @Test
    void badSpecsNameWhatIsWrong() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TeamCommand.parse("./start.sh {port}"))
                .getMessage().contains("NAME=COMMAND"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TeamCommand.parse("X=  "))
                .getMessage().contains("empty"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TeamCommand.parse("X=go {prot} {port}"))
                .getMessage().contains("unknown placeholder {prot}"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TeamCommand.parse("bad name=go {port}"))
                .getMessage().contains("team name 'bad name'"));
    }
}

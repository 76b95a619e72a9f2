package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.model.field.MjField;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** MjRuntime over the real recording (comm/src/test/resources/rcssservermj) and over broken input. */
class MjRuntimeTest {
    private static final Path RECORDING = Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt");

    @Test
    void answersEveryRecordedMessageWithAllT1JointsAndBeamsFirst() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        String first = r.update(lines.get(0));
        assertTrue(first.startsWith("(beam "), "off the field before kick-off: beam first, got " + first.substring(0, 30));
        for (String a : List.of("lle4", "rle4", "lle5", "rle5")) assertTrue(first.contains("(" + a + " "), a + " commanded");
        for (String line : lines.subList(1, lines.size())) {
            String reply = r.update(line);
            assertTrue(reply.startsWith("(") && reply.endsWith(")"), reply);
        }
        assertEquals(lines.size(), r.cycles());
        assertEquals(0, r.malformed());
        assertTrue(r.beams() >= 1);
    }

    @Test
    void aBrokenMessageIsCountedAndAnsweredWithTheLastCommands() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        r.update(lines.get(5));
        // a say is never repeated (it would be a replay): the joint commands only
        String good = r.update(lines.get(6)).replaceAll("\\(SPK [^)]*\\)", "");
        String line = lines.get(7);
        for (String broken : List.of(line.substring(0, line.length() / 2), "(time (now 1.0)", ")))", "(pos (n torso_pos) (p a b c))", "")) {
            String reply = r.update(broken);
            assertEquals(good, reply, "the last joint commands again for '" + broken + "'");
        }
        assertEquals(4, r.malformed(), "the empty message is a valid (empty) perception, the other four are not");
    }

    @Test
    void aUniformNumberBeyondTheRuleBookIsRefusedBeforeConnecting() {
        int status = MjPlayer.run(phalanx.agent.PlayerOptions.parse("--server", "mj", "--unum", "9", "--connect-timeout", "0"));
        assertEquals(2, status, "ssim has 7 players a side");
    }
}

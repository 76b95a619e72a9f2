package phalanx.comm.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.sexp.MalformedMessageException;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class MjPerceptionParserTest {
    static List<String> recording() throws Exception {
        try (InputStream in = MjPerceptionParserTest.class.getResourceAsStream("/rcssservermj/t1-standing.txt")) {
            return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1).lines().toList();
        }
    }

    @Test
    void everyRecordedMessageParsesWithCheckableFacts() throws Exception {
        List<String> lines = recording();
        assertEquals(300, lines.size());
        MjPerceptionParser parser = new MjPerceptionParser();
        double prev = Double.NaN;
        int seeCount = 0;
        for (int i = 0; i < lines.size(); i++) {
            MjPerception m = parser.parse(lines.get(i));
            assertEquals(23, m.joints().size(), "message " + i);
            assertTrue(m.joints().containsKey("q_llj1"));
            if (i > 0) assertEquals(0.02, m.time() - prev, 1e-6, "message " + i);
            prev = m.time();
            double[] q = m.quat();
            assertEquals(1.0, Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), 2e-3);
            assertEquals("BeforeKickOff", m.playMode());
            assertEquals("Phalanx", m.teamLeft());
            assertEquals(0.0, m.gameTime());
            if (i >= 4) { // beamed; the limp robot then falls, its torso moving up to ~0.3 m
                assertEquals(-3.0, m.pos()[0], i < 20 ? 0.1 : 0.4, "message " + i);
                assertEquals(0.0, m.pos()[1], 0.1, "message " + i);
            }
            if (!m.seen().isEmpty()) seeCount++;
        }
        assertEquals(lines.stream().filter(l -> l.contains("(pol")).count(), seeCount); // lying, the See is empty
    }

    @Test
    void truncationsAndByteFlipsOnlyThrowTheParsersException() throws Exception {
        List<String> lines = recording();
        MjPerceptionParser parser = new MjPerceptionParser();
        Random rnd = new Random(20L);
        String[] inserts = {"(", ")", "()", " ", "nan", "1e999", "abc", "\u0000", "(See", "(pol", "(P (team"};
        int errors = 0;
        for (int k = 0; k < 20000; k++) {
            StringBuilder sb = new StringBuilder(lines.get(rnd.nextInt(lines.size())));
            switch (rnd.nextInt(3)) {
                case 0 -> sb.setLength(rnd.nextInt(sb.length()));
                case 1 -> sb.setCharAt(rnd.nextInt(sb.length()), (char) rnd.nextInt(256));
                default -> sb.insert(rnd.nextInt(sb.length()), inserts[rnd.nextInt(inserts.length)]);
            }
            try {
                parser.parse(sb.toString());
            } catch (MalformedMessageException e) {
                errors++;
            }
        }
        assertTrue(errors > 1000, "errors " + errors);
    }

    @Test
    void micPairsAreTypedAndBadOnesSkippedAndCounted() throws Exception {
        MjPerceptionParser parser = new MjPerceptionParser();
        MjPerception m = parser.parse("(time (now 1.5))(MIC hear (-90 pQ==)(89 +F2GkAJK1r2jQA==)(12 abc)(x AA==)(5)(7 AA== BB==))");
        assertEquals(List.of(new MjPerception.Heard(-90, new byte[] {(byte) 0xa5}),
                new MjPerception.Heard(89, new byte[] {(byte) 0xf8, 0x5d, (byte) 0x86, (byte) 0x90, 0x02, 0x4a, (byte) 0xd6,
                        (byte) 0xbd, (byte) 0xa3, 0x40})), m.heard());
        assertEquals(4, m.heardSkipped());
        MjPerception quiet = parser.parse("(MIC hear )");
        assertEquals(List.of(), quiet.heard());
        assertEquals(0, quiet.heardSkipped());
        // Heard keeps its own copy of the bytes
        byte[] b = {1, 2};
        MjPerception.Heard h = new MjPerception.Heard(0, b);
        b[0] = 9;
        h.bytes()[1] = 9;
        assertArrayEquals(new byte[] {1, 2}, h.bytes());
        assertThrows(MalformedMessageException.class, () -> parser.parse("(MIC hear (1 AA==)"));
    }
}

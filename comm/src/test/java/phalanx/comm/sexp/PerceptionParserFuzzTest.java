package phalanx.comm.sexp;

import org.junit.jupiter.api.Test;
import phalanx.comm.recording.Recordings;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Mutates real messages 100,000 times with a fixed seed (truncation, unbalanced parentheses,
 * garbage bytes, non-numbers, huge numbers, empty lists, NaN, deep nesting): the parser returns a
 * perception or throws MalformedMessageException; nothing else escapes. Uses ../shared/recordings
 * when present, else a built-in message, so the test always runs.
 */
class PerceptionParserFuzzTest {
    private static final String BUILT_IN = "(time (now 0.52))(GS (unum 1) (team left) (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))"
            + "(hear Probe 0.00 -47.72 fromTwo)(GYR (n torso) (rt 0.00 -0.00 0.00))(ACC (n torso) (a 0.00 0.00 9.81))"
            + "(HJ (n hj1) (ax -0.00))(See (F1L (pol 18.70 53.49 -5.25)) (B (pol 1.89 0.33 -58.15))"
            + " (P (team Dummy) (id 1) (head (pol 20.40 58.29 0.16))) (L (pol 1.90 0.28 -59.80) (pol 11.14 -0.10 -8.60)))"
            + "(FRP (n rf) (c 0.00 -0.01 -0.01) (f 0.00 -0.10 106.88))";
    private static final String[] INSERTS = {"(", ")", "((", "))", "()", " ", "nan", "-inf", "1e308", "1e999",
            "99999999999999999999999", "abc", "\u0000", "\u00ff", "(see", "(pol", "-", ".", "..", "e", "(n)", "(HJ", "(P (team"};

    @Test
    void mutatedMessagesNeverEscapeTheDocumentedException() throws Exception {
        List<byte[]> seeds = new ArrayList<>();
        seeds.add(BUILT_IN.getBytes(StandardCharsets.ISO_8859_1));
        if (Recordings.dir().isPresent()) {
            for (Path rec : Recordings.all()) {
                List<String> lines = Recordings.perceptorMessages(rec);
                for (int i = 0; i < lines.size(); i += 97) seeds.add(lines.get(i).getBytes(StandardCharsets.ISO_8859_1));
            }
        }
        Random rnd = new Random(20121022L);
        PerceptionParser parser = new PerceptionParser();
        int parsed = 0, rejected = 0;
        for (int i = 0; i < 100_000; i++) {
            byte[] m = mutate(seeds.get(rnd.nextInt(seeds.size())), rnd);
            try {
                assertNotNull(parser.parse(m, 0, m.length));
                parsed++;
            } catch (MalformedMessageException e) {
                assertNotNull(e.getMessage());
                rejected++;
            } catch (RuntimeException | StackOverflowError e) {
                fail("mutation " + i + " escaped with " + e + " on: " + new String(m, StandardCharsets.ISO_8859_1), e);
            }
        }
        assertTrue(parsed > 1000 && rejected > 1000, "mutations should both parse and fail: " + parsed + "/" + rejected);
    }

    private static byte[] mutate(byte[] src, Random rnd) {
        byte[] m = src.clone();
        int kinds = 1 + rnd.nextInt(3);
        for (int k = 0; k < kinds; k++) {
            switch (rnd.nextInt(7)) {
                case 0 -> m = java.util.Arrays.copyOf(m, rnd.nextInt(m.length + 1)); // truncation
                case 1 -> { if (m.length > 0) m[rnd.nextInt(m.length)] = (byte) rnd.nextInt(256); } // garbage byte
                case 2 -> m = insert(m, rnd.nextInt(m.length + 1), INSERTS[rnd.nextInt(INSERTS.length)]);
                case 3 -> m = insert(m, rnd.nextInt(m.length + 1), "(".repeat(1 + rnd.nextInt(50_000))); // deep nesting
                case 4 -> { // replace a number with something else
                    int at = rnd.nextInt(Math.max(1, m.length));
                    for (int j = at; j < m.length; j++) {
                        if (m[j] >= '0' && m[j] <= '9') { m = insert(m, j, INSERTS[rnd.nextInt(INSERTS.length)]); break; }
                    }
                }
                case 5 -> { if (m.length > 1) { int a = rnd.nextInt(m.length); m = remove(m, a, Math.min(m.length, a + rnd.nextInt(20))); } }
                default -> m = insert(m, rnd.nextInt(m.length + 1), "()");
            }
        }
        return m;
    }

    private static byte[] insert(byte[] m, int at, String s) {
        byte[] ins = s.getBytes(StandardCharsets.ISO_8859_1);
        byte[] r = new byte[m.length + ins.length];
        System.arraycopy(m, 0, r, 0, at);
        System.arraycopy(ins, 0, r, at, ins.length);
        System.arraycopy(m, at, r, at + ins.length, m.length - at);
        return r;
    }

    private static byte[] remove(byte[] m, int from, int to) {
        byte[] r = new byte[m.length - (to - from)];
        System.arraycopy(m, 0, r, 0, from);
        System.arraycopy(m, to, r, from, m.length - to);
        return r;
    }
}

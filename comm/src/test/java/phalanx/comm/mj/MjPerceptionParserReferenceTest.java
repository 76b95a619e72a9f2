package phalanx.comm.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.sexp.MalformedMessageException;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The single-pass {@link MjPerceptionParser} against the tree parser it replaced ({@link TreeReferenceParser}):
 * field-for-field identical results (doubles bit for bit, -0.0 included; map and list order) on every recorded
 * message and on hand-made ones with the nodes the recording lacks (P, TCH, MIC, exponents), and the same
 * outcome - both throw MalformedMessageException or both give identical results - on mutated messages.
 */
class MjPerceptionParserReferenceTest {
    private final MjPerceptionParser parser = new MjPerceptionParser();
    private final TreeReferenceParser reference = new TreeReferenceParser();

    /** Every field, doubles through Double.toString (distinct doubles, distinct text; -0.0 is not 0.0). */
    static String fields(MjPerception m) {
        StringBuilder b = new StringBuilder();
        b.append(m.time()).append('|').append(m.gameTime()).append('|').append(m.playMode()).append('|')
                .append(m.teamLeft()).append('|').append(m.teamRight()).append('|').append(m.scoreLeft()).append('|')
                .append(m.scoreRight()).append('|').append(Arrays.toString(m.quat())).append('|')
                .append(Arrays.toString(m.pos())).append('|').append(Arrays.toString(m.gyro())).append('|')
                .append(Arrays.toString(m.acc())).append('|');
        for (Map.Entry<String, double[]> e : m.joints().entrySet()) {
            b.append(e.getKey()).append('=').append(Arrays.toString(e.getValue())).append(';');
        }
        b.append('|').append(m.touch()).append('|').append(m.seen()).append('|').append(m.heard()).append('|').append(m.heardSkipped());
        return b.toString();
    }

    /** "fails" when the parser throws MalformedMessageException (any other exception fails the test). */
    private static String outcome(String message, Parse p) {
        try {
            return fields(p.parse(message));
        } catch (MalformedMessageException e) {
            return "fails";
        }
    }

    private interface Parse { MjPerception parse(String m) throws MalformedMessageException; }

    private void assertSameOutcome(String message) {
        String expected = outcome(message, reference::parse);
        assertEquals(expected, outcome(message, parser::parse), () -> "message: " + message);
    }

    static final List<String> HAND_MADE = List.of(
            "",
            "  (time (now 1.5e2))(GS (t 12.25)(pm PlayOn)(tl A)(tr B)(sl 2)(sr 3))",
            "(See (B (pol 1.0 -2.5 0.125))(P (team Them)(id 7)(head (pol 3.1 4.2 -5.3))"
                    + "(rlowerarm (pol 3.0 4.0 -5.0))(llowerarm (pol 2.9 3.9 -4.9)))(x_cuc (pol 15.71 11.03 -4.0)))",
            "(See (P (head (pol 1 2 3)) (id 9) (team Us) (team Other) (P 1) ((x)) (id 3)))",
            "(TCH n lf val 1)(TCH n rf val 0 extra (x y))(TCH (n) rf (val) 1)",
            "(MIC (t 12.0) (msg hello) () ((a b) c))(MIC)",
            "(MIC hear (-90 pQ==)(89 ux1tEw==)(0 +F2GkAJK1r2jQA==))(MIC hear )(MIC hear (90 abc)(90 ab=c)(x AA==)(1e999 AA==))",
            "(MIC hear (12.5 AAAA) (NaN AA==) (1 AA== x) (1 (AA==)) ((1) AA==) (1) (-0 /+8=))",
            "(time (now 1.0) (now abc))(time (x) (now -0.0))",
            "(GS (t) (pm) (sl 1.9) (sr -2.5) ((t 5)) (q 1) (t 1d) (t .5) (t 5.) (t +3))",
            "(HJ (n a)(ax 1)(vx 2))(HJ (vx 3)(ax 4)(n a)(n b))(HJ (n b)(ax 0x1p3)(vx 1e-3))",
            "(quat (q 0.70710678118654 1.23456789012345678 -0.0 1E2))(pos (p 1 2 3)(p x y z))",
            "(GYR (rt 0.000000000000001 123456789012345 1234567890123456))(ACC (a 00.50 -007 9007199254740993))",
            "(foo (bar (baz))) (time (now 3)) \t\n(unknown 1 2 3)\u2028",
            "(time (now 1))junk",
            "(time (now NaN))",
            "(time (now Infinity))",
            "(time (now 1e999))",
            "(time (now \u00001.5))",
            "(time (now 1.5\u0001))",
            "(See (P (id 1)(head (pol 1 2 3))))",
            "(See (P (team)(id 1)))",
            "(See (P (team (x))(id 1)))",
            "(See (B (pol 1 2)))",
            "(See (B))",
            "(See ((B (pol 1 2 3))) (B (pol 1 2 3 4) (pol 1 2 3)))",
            "(See (B (pol 1 2 3) (pol x)) B C)",
            "(TCH n lf val)",
            "(TCH n (lf) val 1)",
            "(HJ (n a b)(ax 1)(vx 2))",
            "(HJ (n a)(ax 1))",
            "(quat (q 1 2 3))",
            "(GS (t x))",
            "(GS (pm (PlayOn)))",
            "(((((((((((((((((((((((((((((((((a)))))))))))))))))))))))))))))))))",
            "((((((((((((((((((((((((((((((((((a))))))))))))))))))))))))))))))))))",
            "(time (now 1)",
            "(time (now 1)))",
            ")",
            "x");

    @Test
    void everyRecordedMessageGivesTheTreeReferencesFields() throws Exception {
        List<String> lines = MjPerceptionParserTest.recording();
        for (String line : lines) {
            MjPerception m = parser.parse(line);
            assertEquals(fields(reference.parse(line)), fields(m), () -> "message: " + line);
        }
        assertEquals(300, lines.size());
    }

    @Test
    void handMadeMessagesGiveTheTreeReferencesOutcome() {
        for (String m : HAND_MADE) assertSameOutcome(m);
        int fails = 0;
        for (String m : HAND_MADE) if (outcome(m, parser::parse).equals("fails")) fails++;
        assertTrue(fails > 20 && fails < HAND_MADE.size() - 8, "fails " + fails); // both kinds are exercised
    }

    @Test
    void plainDecimalsAreDoubleParseDoubleBitForBit() throws Exception {
        Random rnd = new Random(21L);
        for (int k = 0; k < 20000; k++) {
            StringBuilder t = new StringBuilder();
            if (rnd.nextBoolean()) t.append('-');
            int digits = 1 + rnd.nextInt(18);
            int point = rnd.nextInt(digits + 1);
            for (int i = 0; i < digits; i++) {
                if (i == point && i > 0) t.append('.');
                t.append((char) ('0' + rnd.nextInt(10)));
            }
            double expected = Double.parseDouble(t.toString());
            double got = parser.parse("(time (now " + t + "))").time();
            assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(got), t::toString);
        }
    }

    @Test
    void mutatedMessagesGiveTheTreeReferencesOutcome() throws Exception {
        List<String> base = new ArrayList<>(MjPerceptionParserTest.recording());
        base.addAll(HAND_MADE.subList(1, 6));
        Random rnd = new Random(22L);
        String[] inserts = {"(", ")", "()", " ", "nan", "1e999", "abc", "\u0000", "(See", "(pol", "(P (team",
                "(n x)", "(pol 1 2 3)", "(now 2)", "(team T)", "-", ".", "e5", "\u2028", "\u00a0"};
        int fails = 0;
        for (int k = 0; k < 40000; k++) {
            String line = base.get(rnd.nextInt(base.size()));
            StringBuilder sb = new StringBuilder(line);
            int at = rnd.nextInt(sb.length());
            switch (rnd.nextInt(5)) {
                case 0 -> sb.setLength(at);
                case 1 -> sb.setCharAt(at, (char) rnd.nextInt(256));
                case 2 -> sb.deleteCharAt(at);
                case 3 -> sb.insert(at, line, rnd.nextInt(line.length()), line.length()); // a tail again
                default -> sb.insert(at, inserts[rnd.nextInt(inserts.length)]);
            }
            String m = sb.toString();
            assertSameOutcome(m);
            if (outcome(m, parser::parse).equals("fails")) fails++;
        }
        assertTrue(fails > 2000 && fails < 38000, "fails " + fails);
    }
}

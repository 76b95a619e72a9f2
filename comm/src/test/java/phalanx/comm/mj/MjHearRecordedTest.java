package phalanx.comm.mj;

import org.junit.jupiter.api.Test;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The MIC node as rcssservermj sends it, on a recording of a hearing T1 (t1-hear.txt, see the resources
 * README): {@code (MIC hear (AZIMUTH BASE64)(AZIMUTH BASE64)...)}, {@code (MIC hear )} when all it heard
 * was filtered out, no MIC when nothing was said.
 */
class MjHearRecordedTest {
    /** The whole node: the sensor name, a space, pairs without spaces between them. */
    static final Pattern MIC = Pattern.compile("\\(MIC hear ((?:\\(-?\\d+ [A-Za-z0-9+/]+={0,2}\\))*)\\)");
    static final Pattern PAIR = Pattern.compile("\\((-?\\d+) ([A-Za-z0-9+/]+={0,2})\\)");

    static List<String> recording() throws Exception {
        try (InputStream in = MjHearRecordedTest.class.getResourceAsStream("/rcssservermj/t1-hear.txt")) {
            return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1).lines().toList();
        }
    }

    @Test
    void theParserGivesEveryPairOfTheWireFormat() throws Exception {
        List<String> lines = recording();
        assertEquals(100, lines.size());
        MjPerceptionParser parser = new MjPerceptionParser();
        int withMic = 0, empty = 0, pairs = 0, nine = 0, ten = 0;
        double lastTime = Double.NaN;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            MjPerception p = parser.parse(line);
            if (i > 0) assertEquals(0.02, p.time() - lastTime, 1e-6, "line " + i);
            lastTime = p.time();
            assertEquals(0, p.heardSkipped(), "line " + i);
            int at = line.indexOf("(MIC");
            if (at < 0) {
                assertTrue(i < 2, "only the first two perceptions (before anything said was heard) lack a MIC, line " + i);
                assertEquals(List.of(), p.heard());
                continue;
            }
            withMic++;
            assertEquals(at, line.lastIndexOf("(MIC"), "one MIC a perception");
            assertTrue(line.lastIndexOf("(HJ") < at, "MIC follows the joints");
            assertTrue(line.indexOf("(See") < 0 || line.indexOf("(See") > at, "and precedes See");
            Matcher m = MIC.matcher(line);
            assertTrue(m.find(at) && m.start() == at, "line " + i + ": " + line.substring(at, Math.min(line.length(), at + 80)));
            List<MjPerception.Heard> raw = new ArrayList<>();
            Matcher pm = PAIR.matcher(m.group(1));
            while (pm.find()) raw.add(new MjPerception.Heard(Integer.parseInt(pm.group(1)), Base64.getDecoder().decode(pm.group(2))));
            assertEquals(raw, p.heard(), "line " + i);
            if (raw.isEmpty()) empty++;
            for (MjPerception.Heard h : p.heard()) {
                pairs++;
                assertEquals(Math.rint(h.azimuth()), h.azimuth(), "whole degrees");
                assertTrue(h.azimuth() >= -180 && h.azimuth() <= 180);
                int n = h.bytes().length;
                assertTrue(n == 9 || n == 10, "only 9- and 10-byte messages were said and delivered, got " + n);
                if (n == 9) nine++; else ten++;
            }
            assertTrue(p.heard().size() <= 2, "two other T1s spoke, the hearer never hears itself");
        }
        assertEquals(98, withMic);
        assertEquals(5, empty, "the 11-byte sayings: broadcast, then dropped for every hearer");
        assertEquals(141, pairs);
        assertEquals(5, nine);
        assertEquals(136, ten);
    }
}

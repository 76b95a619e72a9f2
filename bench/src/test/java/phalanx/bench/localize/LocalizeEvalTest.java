package phalanx.bench.localize;

import phalanx.comm.recording.GroundTruth;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import phalanx.comm.recording.Recordings;
import phalanx.localization.LocalizationConfig;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The targets on every recording with ground truth (needs ../shared/recordings; skipped
 * with a message when missing): self median < 0.15 m, p95 < 0.5 m; ball median < 0.2 m.
 */
class LocalizeEvalTest {
    private static final String[] WITH_TRUTH = {"S1", "S2", "S3", "S4_agent1", "S4_agent2", "S5_agent1", "S5_agent7", "S6"};

    @BeforeAll
    static void needRecordings() {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
    }

    private static String[] args(String... opts) {
        String[] a = new String[opts.length + WITH_TRUTH.length];
        System.arraycopy(opts, 0, a, 0, opts.length);
        for (int i = 0; i < WITH_TRUTH.length; i++) a[opts.length + i] = Recordings.named(WITH_TRUTH[i]).toString();
        return a;
    }

    private static String run(String... a) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int rc = LocalizeEval.run(a, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, rc, err.toString(StandardCharsets.UTF_8));
        return out.toString(StandardCharsets.UTF_8);
    }

    private static double field(String summary, String key) {
        for (String kv : summary.trim().split(" ")) if (kv.startsWith(key + "=")) return Double.parseDouble(kv.substring(key.length() + 1));
        throw new AssertionError("no " + key + " in " + summary);
    }

    @Test
    void bothFiltersMeetTheTargetsOnAllRecordings() {
        for (String f : new String[] {"ekf", "fifo"}) {
            String out = run(args("--filter", f));
            String[] lines = out.trim().split("\n");
            String last = lines[lines.length - 1];
            assertTrue(last.startsWith("self_median_m="), last);
            assertTrue(field(last, "self_median_m") < 0.15, f + ": " + last);
            assertTrue(field(last, "self_p95_m") < 0.5, f + ": " + last);
            assertTrue(field(last, "ball_median_m") < 0.2, f + ": " + last);
            assertTrue(field(last, "fix_rate") > 0.7, f + ": " + last);
            for (String r : WITH_TRUTH) assertTrue(out.contains(r + " "), "a line for " + r);
        }
    }

    @Test
    void eachRecordingMeetsTheTargetsOnItsOwn() throws IOException {
        for (String r : WITH_TRUTH) {
            LocalizeEval.Result res = LocalizeEval.run(Recordings.named(r), LocalizationConfig.DEFAULT);
            assertTrue(res.selfSamples() > 80, r + ": " + res.selfSamples() + " cycles with a self belief");
            assertTrue(res.selfMedian() < 0.15, r + " self median " + res.selfMedian());
            assertTrue(res.selfP95() < 0.5, r + " self p95 " + res.selfP95());
            assertTrue(res.thetaMedian() < 2, r + " theta median " + res.thetaMedian());
            assertTrue(res.ballMedian() < 0.2, r + " ball median " + res.ballMedian());
        }
    }

    @Test
    void badArgumentsGetAClearMessage() throws IOException {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8), o = new PrintStream(new ByteArrayOutputStream());
        assertEquals(2, LocalizeEval.run(new String[] {}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("name at least one recording"));
        assertEquals(2, LocalizeEval.run(new String[] {"--filter", "kalman", Recordings.named("S1").toString()}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("unknown filter 'kalman'"));
        assertEquals(2, LocalizeEval.run(new String[] {"--frobnicate"}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("unknown option '--frobnicate'"));
        assertEquals(2, LocalizeEval.run(new String[] {Recordings.named("NOPE").toString()}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("NOPE_perceptors.txt is missing"));
        assertEquals(2, LocalizeEval.run(new String[] {Recordings.named("M1").toString()}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("has no ground truth"));
    }

    @Test
    void aBrokenGroundTruthFileNamesTheLine() throws IOException {
        Path f = Files.createTempFile("gt", ".txt");
        try {
            Files.writeString(f, "# header\n0.52 0 BeforeKickOff 1 2\n");
            IOException e = assertThrows(IOException.class, () -> GroundTruth.read(f));
            assertTrue(e.getMessage().contains(":2: expected 19 fields, found 5"), e.getMessage());
            Files.writeString(f, "0.52 0 X 1 2 3 1 0 0 0 1 0 0 0 one 7 0 0 0.04\n");
            e = assertThrows(IOException.class, () -> GroundTruth.read(f));
            assertTrue(e.getMessage().contains(":1: not a number"), e.getMessage());
        } finally {
            Files.deleteIfExists(f);
        }
    }

    @Test
    void groundTruthReadsNanAndTheRightSideConversion() throws IOException {
        var lines = GroundTruth.read(Recordings.groundTruthFile(Recordings.named("S6")));
        assertFalse(lines.get(0).hasTorso(), "first messages: nan");
        var l304 = lines.get(303);
        assertEquals(10.0, l304.x(), 0.01);
        assertEquals(-150.0, l304.yawDeg(), 0.5);
        var own = new phalanx.model.field.Pose2(-10, -4, 30);
        var f = LocalizeEval.toField(own, phalanx.comm.perception.Side.RIGHT);
        assertEquals(10, f.x(), 1e-9);
        assertEquals(4, f.y(), 1e-9);
        assertEquals(-150, f.thetaDeg(), 1e-9);
    }
}

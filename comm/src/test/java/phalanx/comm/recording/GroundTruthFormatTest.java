package phalanx.comm.recording;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.GZIPOutputStream;

import static org.junit.jupiter.api.Assertions.*;

/** The recorder's ground-truth lines read back as written, and gzipped recordings read like plain ones. */
class GroundTruthFormatTest {
    /** Torso facing -x: R's forward column (r12, r22, r32) = (-1, 0, 0), so yaw = atan2(r22, r12) = 180°. */
    private static final double[] TURNED = {0, -1, 0, 1, 0, 0, 0, 0, 1};

    @Test
    void aLineIsWrittenAsTheSharedRecordingsWriteIt() {
        // S2's line 30, shaped like the shared file's: "0.96 0.16 PlayOn 3.00000 -4.00000 0.39000 1.000000 ..."
        double[] r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        assertEquals("0.96 0.16 PlayOn 3.00000 -4.00000 0.39000 1.000000 0.000000 0.000000 0.000000 1.000000 0.000000 0.000000 0.000000 1.000000 90.000 5.00000 -1.00000 0.04057",
                GroundTruth.format(0.96, 0.16, "PlayOn", 3, -4, 0.39, r, 5, -1, 0.04057));
        assertEquals("0.44 0 BeforeKickOff nan nan nan nan nan nan nan nan nan nan nan nan nan 0.00000 0.00000 0.04176",
                GroundTruth.format(0.44, 0, "BeforeKickOff", Double.NaN, Double.NaN, Double.NaN, null, 0, 0, 0.04176));
    }

    @Test
    void whatIsWrittenIsReadBack(@TempDir Path dir) throws IOException {
        Path f = dir.resolve("X_groundtruth.txt.gz");
        try (OutputStream o = new GZIPOutputStream(Files.newOutputStream(f))) {
            String text = GroundTruth.HEADER + "\n"
                    + GroundTruth.format(1.5, 0.3, "PlayOn", -2.5, 1.25, 0.384, TURNED, 1, 2, 0.042) + "\n"
                    + GroundTruth.format(1.52, 0.32, "PlayOn", Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, Double.NaN, Double.NaN) + "\n";
            o.write(text.getBytes(StandardCharsets.US_ASCII));
        }
        assertEquals(f, Recordings.groundTruthFile(dir.resolve("X")), "the .gz file stands for the plain one");
        List<GroundTruth.Line> lines = GroundTruth.read(Recordings.groundTruthFile(dir.resolve("X")));
        assertEquals(2, lines.size());
        GroundTruth.Line a = lines.get(0);
        assertEquals(1.5, a.now(), 1e-9);
        assertEquals(-2.5, a.x(), 1e-9);
        assertEquals(1.25, a.y(), 1e-9);
        assertEquals(180.0, a.yawDeg(), 1e-9, "forward column (-1, 0, 0): facing -x");
        assertEquals(1.0, a.ballX(), 1e-9);
        assertFalse(a.fallen());
        assertFalse(lines.get(1).hasTorso());
        assertFalse(lines.get(1).hasBall());
    }

    @Test
    void aPlainFileIsPreferredToAGzippedOne(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("Y_perceptors.txt"), "(time (now 0.02))\n");
        Files.writeString(dir.resolve("Y_perceptors.txt.gz"), "not gzip");
        assertEquals(List.of("(time (now 0.02))"), Recordings.perceptorMessages(dir.resolve("Y")));
    }

    @Test
    void aBrokenGzipIsAnIOException(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("Z_perceptors.txt.gz"), "not gzip");
        assertThrows(IOException.class, () -> Recordings.perceptorMessages(dir.resolve("Z")));
    }
}

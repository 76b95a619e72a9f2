package phalanx.comm.recording;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

/**
 * Finds the real server recordings in {@code ../shared/recordings} (format in its README) and reads
 * them. A recording is named by its path prefix: {@code .../S1} stands for {@code S1_perceptors.txt},
 * {@code S1_effectors.txt}, {@code S1_groundtruth.txt}.
 */
public final class Recordings {
    private Recordings() {}

    /**
     * The shared folder: system property {@code phalanx.shared}, else environment variable
     * {@code PHALANX_SHARED}, else {@code ../shared} from the working directory.
     */
    public static Path sharedDir() {
        String p = System.getProperty("phalanx.shared");
        if (p == null || p.isBlank()) p = System.getenv("PHALANX_SHARED");
        if (p == null || p.isBlank()) p = "../shared";
        return Paths.get(p).toAbsolutePath().normalize();
    }

    /** The recordings folder, if it is there. */
    public static Optional<Path> dir() {
        Path d = sharedDir().resolve("recordings");
        return Files.isDirectory(d) ? Optional.of(d) : Optional.empty();
    }

    /** The message tests print when they skip because the recordings are missing. */
    public static String missingMessage() {
        return "needs the real server recordings in " + sharedDir().resolve("recordings")
                + " (set -Dphalanx.shared or PHALANX_SHARED); skipped";
    }

    /** Every {@code *_perceptors.txt} in the recordings folder, as path prefixes, sorted. */
    public static List<Path> all() throws IOException {
        Optional<Path> d = dir();
        if (d.isEmpty()) return List.of();
        try (Stream<Path> s = Files.list(d.get())) {
            return s.map(Path::getFileName).map(Path::toString)
                    .filter(n -> n.endsWith("_perceptors.txt")).sorted()
                    .map(n -> d.get().resolve(n.substring(0, n.length() - "_perceptors.txt".length())))
                    .toList();
        }
    }

    /** A named recording, e.g. {@code "S4_agent2"}, in the shared folder. */
    public static Path named(String name) {
        return sharedDir().resolve("recordings").resolve(name);
    }

    /**
     * The recording's files; each may be gzipped ({@code S1_perceptors.txt.gz}, the project's own fixtures are):
     * the plain file when it exists, else the {@code .gz} one when that exists, else the plain name.
     */
    public static Path perceptorFile(Path prefix) { return sibling(prefix, "_perceptors.txt"); }
    public static Path effectorFile(Path prefix) { return sibling(prefix, "_effectors.txt"); }
    public static Path groundTruthFile(Path prefix) { return sibling(prefix, "_groundtruth.txt"); }
    /** The walk's odometry per perceptor line (the project's own recordings only; not in the shared format). */
    public static Path odometryFile(Path prefix) { return sibling(prefix, "_odometry.txt"); }

    /** The perceptor messages, one per line, exactly as the server sent them. */
    public static List<String> perceptorMessages(Path prefix) throws IOException {
        return lines(perceptorFile(prefix));
    }

    /** A text file's lines (ISO-8859-1, as the server's bytes), gunzipped when its name ends in {@code .gz}. */
    public static List<String> lines(Path file) throws IOException {
        if (!file.getFileName().toString().endsWith(".gz")) return Files.readAllLines(file, StandardCharsets.ISO_8859_1);
        try (BufferedReader r = new BufferedReader(new InputStreamReader(new GZIPInputStream(Files.newInputStream(file)),
                StandardCharsets.ISO_8859_1))) {
            return r.lines().toList();
        } catch (UncheckedIOException e) {
            throw new IOException(file + ": " + e.getCause().getMessage() + " (a truncated or damaged gzip file)", e.getCause());
        } catch (java.util.zip.ZipException | java.io.EOFException e) {
            throw new IOException(file + ": " + e.getMessage() + " (a truncated or damaged gzip file)", e);
        }
    }

    private static Path sibling(Path prefix, String suffix) {
        Path plain = prefix.resolveSibling(prefix.getFileName() + suffix);
        Path gz = prefix.resolveSibling(prefix.getFileName() + suffix + ".gz");
        return !Files.exists(plain) && Files.exists(gz) ? gz : plain;
    }
}

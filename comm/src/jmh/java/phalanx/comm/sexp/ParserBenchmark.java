package phalanx.comm.sexp;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import phalanx.comm.perception.Perception;
import phalanx.comm.recording.Recordings;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Parses every perceptor message of every shared recording, one message per invocation.
 * Throughput in MB/s = ops/s x mean message size (printed at setup); run with -prof gc for
 * the allocation per message (gc.alloc.rate.norm). Script: scripts/phalanx bench parser.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class ParserBenchmark {
    private byte[][] messages;
    private byte[][] withoutVision;
    private int next;
    private int nextPlain;
    private final PerceptionParser parser = new PerceptionParser();

    @Setup(Level.Trial)
    public void load() throws Exception {
        List<byte[]> all = new ArrayList<>();
        long bytes = 0;
        for (Path rec : Recordings.all()) {
            for (String line : Recordings.perceptorMessages(rec)) {
                byte[] b = line.getBytes(StandardCharsets.ISO_8859_1);
                all.add(b);
                bytes += b.length;
            }
        }
        if (all.isEmpty()) throw new IllegalStateException(Recordings.missingMessage());
        messages = all.toArray(new byte[0][]);
        withoutVision = all.stream().filter(m -> !new String(m, StandardCharsets.ISO_8859_1).contains("(See ")).toArray(byte[][]::new);
        System.out.printf("%nmessages=%d mean_bytes=%.1f%n", messages.length, (double) bytes / messages.length);
    }

    @Benchmark
    public Perception parse() throws MalformedMessageException {
        byte[] m = messages[next];
        next = next + 1 == messages.length ? 0 : next + 1;
        return parser.parse(m, 0, m.length);
    }

    /**
     * Messages without vision: their perception is a fixed set of objects (Perception, GameState,
     * two Vector3, JointAngles and its double[24], about 370 bytes), so any allocation above that
     * would be the parser's own garbage.
     */
    @Benchmark
    public Perception parseWithoutVision() throws MalformedMessageException {
        byte[] m = withoutVision[nextPlain];
        nextPlain = nextPlain + 1 == withoutVision.length ? 0 : nextPlain + 1;
        return parser.parse(m, 0, m.length);
    }
}

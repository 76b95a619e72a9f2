package phalanx.comm.mj;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import phalanx.comm.sexp.MalformedMessageException;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Parses every message of the recorded rcssservermj stream (comm/src/test/resources/rcssservermj), one per
 * invocation. MB/s = ops/s x mean message size (printed at setup), as ParserBenchmark does for SimSpark.
 * {@code parseTreeReference} times the tree parser MjPerceptionParser replaced (TreeReferenceParser, test
 * source set) on the same stream, so old and new are measured back to back under the same load.
 * Run from the project root: gradle :comm:jmh -PjmhArgs='MjParserBenchmark -f 1 -wi 3 -w 2 -i 5 -r 2'.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class MjParserBenchmark {
    private String[] messages;
    private int next;
    private final MjPerceptionParser parser = new MjPerceptionParser();
    private final TreeReferenceParser reference = new TreeReferenceParser();

    @Setup(Level.Trial)
    public void load() throws Exception {
        List<String> lines = Files.readAllLines(Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt"));
        messages = lines.stream().filter(l -> l.startsWith("(")).toArray(String[]::new);
        long bytes = 0;
        for (String m : messages) bytes += m.length();
        System.out.printf("%nmessages=%d mean_bytes=%.1f%n", messages.length, (double) bytes / messages.length);
    }

    @Benchmark
    public MjPerception parse() throws MalformedMessageException {
        String m = messages[next];
        next = next + 1 == messages.length ? 0 : next + 1;
        return parser.parse(m);
    }

    @Benchmark
    public MjPerception parseTreeReference() throws MalformedMessageException {
        String m = messages[next];
        next = next + 1 == messages.length ? 0 : next + 1;
        return reference.parse(m);
    }
}

package phalanx.agent;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import phalanx.comm.perception.Perception;
import phalanx.comm.recording.Recordings;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One whole player cycle (parse, beliefs, team channel, brain, motion, effector text) over a
 * recorded perceptor stream, without the socket: the think time the 20 ms cycle budget is about.
 * Player 1 runs the coordinator too. {@link #parse} is the parser alone on the same stream: its
 * allocation is the perception the cycle must build (agent/README.md, "Measured cost").
 * Script: scripts/phalanx bench think.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class ThinkBenchmark {
    @Param({"S5_agent1", "S5_agent7"})
    public String recording;
    @Param({"1", "7"})
    public int unum;

    private byte[][] messages;
    private int next;
    private PlayerRuntime runtime;
    private final PerceptionParser parser = new PerceptionParser();

    @Setup(Level.Trial)
    public void load() throws Exception {
        List<String> lines = Recordings.perceptorMessages(Recordings.named(recording));
        messages = lines.stream().map(l -> l.getBytes(StandardCharsets.ISO_8859_1)).toArray(byte[][]::new);
        PlayerOptions o = PlayerOptions.parse("--unum", String.valueOf(unum), "--team", "ProbeTeam");
        runtime = new PlayerRuntime(o, Player.parts(o));
    }

    @Benchmark
    public CharSequence cycle() {
        byte[] m = messages[next];
        next = next + 1 == messages.length ? 1 : next + 1; // line 1 is the pre-init message
        return runtime.update(m, m.length);
    }

    @Benchmark
    public Perception parse() throws MalformedMessageException {
        byte[] m = messages[next];
        next = next + 1 == messages.length ? 1 : next + 1;
        return parser.parse(m, 0, m.length);
    }
}

package phalanx.localization.belief;

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
import phalanx.comm.sexp.PerceptionParser;
import phalanx.localization.LocalizationConfig;
import phalanx.model.robot.NaoModel;
import phalanx.model.field.FieldSpec;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One belief-store cycle (every third one has vision), over S5 agent 7's pre-parsed messages
 * (head panning, teammates in view). Average time per cycle; -prof gc for bytes per cycle.
 * gradle :localization:jmh -PjmhArgs='BeliefStoreBenchmark -f 1 -wi 3 -i 5 -prof gc'
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class BeliefStoreBenchmark {
    @Param({"EKF", "FIFO"})
    public String filter;
    private Perception[] cycles;
    private int next;
    private BeliefStore store;

    @Setup(Level.Trial)
    public void load() throws Exception {
        if (Recordings.dir().isEmpty()) throw new IllegalStateException(Recordings.missingMessage());
        PerceptionParser parser = new PerceptionParser();
        List<Perception> all = new ArrayList<>();
        for (String line : Recordings.perceptorMessages(Recordings.named("S5_agent7"))) all.add(parser.parse(line));
        cycles = all.toArray(new Perception[0]);
        store = new BeliefStore(FieldSpec.V066, LocalizationConfig.DEFAULT.withFilter(LocalizationConfig.Filter.valueOf(filter)),
                NaoModel.ofType(4), "ProbeTeam", null, 0);
    }

    @Benchmark
    public WorldBelief cycle() {
        Perception p = cycles[next];
        next = next + 1 == cycles.length ? 3 : next + 1;   // loop past the first, pre-init messages
        return store.update(p);
    }
}

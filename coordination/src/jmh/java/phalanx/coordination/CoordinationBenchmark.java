package phalanx.coordination;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.Blackhole;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.support.ScramSupportMapper;
import phalanx.coordination.support.SupportCost;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * One whole coordination round (all six phases, 11 players, every one reporting type C, nobody inactive,
 * Active mode: 3 active and 7 support players), the same in Support mode (10 support players), and the
 * support mapping alone (7 players as in the first, 10 as in the second), over 256 random situations
 * visited in turn.
 * Run: {@code scripts/phalanx bench coord}, or {@code gradle -q :coordination:jmh -PjmhArgs='CoordinationBenchmark -f 1'}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class CoordinationBenchmark {
    private static final int SITUATIONS = 256;
    private final Coordinator coordinator = new Coordinator();
    private final DynamicProgrammingSupportMapper dp = new DynamicProgrammingSupportMapper();
    private final ScramSupportMapper scram = new ScramSupportMapper();
    private TeamBeliefs[] teams;
    private SupportCost[] support7, support10;
    private int next;

    @Setup(Level.Trial)
    public void setUp() {
        Random rnd = new Random(42);
        FieldSpec f = FieldSpec.V066;
        teams = new TeamBeliefs[SITUATIONS];
        support7 = new SupportCost[SITUATIONS];
        support10 = new SupportCost[SITUATIONS];
        for (int s = 0; s < SITUATIONS; s++) {
            Vector2 ball = point(rnd, 14, 9);
            List<PlayerReport> reports = new ArrayList<>();
            reports.add(PlayerReport.complete(1, new Pose2(-14.5, 0, 0), ball));
            for (int id = 2; id <= 11; id++) {
                Vector2 p = point(rnd, 15, 10);
                reports.add(PlayerReport.complete(id, new Pose2(p.x(), p.y(), rnd.nextDouble() * 360 - 180),
                        ball.plus(point(rnd, 0.3, 0.3))));
            }
            teams[s] = new TeamBeliefs(f, reports);
            support7[s] = instance(rnd, 7);
            support10[s] = instance(rnd, 10);
        }
    }

    private static Vector2 point(Random rnd, double hx, double hy) {
        return new Vector2((rnd.nextDouble() * 2 - 1) * hx, (rnd.nextDouble() * 2 - 1) * hy);
    }

    private static SupportCost instance(Random rnd, int n) {
        List<Vector2> a = new ArrayList<>(), p = new ArrayList<>(), fs = new ArrayList<>(), ft = new ArrayList<>();
        for (int i = 0; i < n; i++) { a.add(point(rnd, 15, 10)); p.add(point(rnd, 14.5, 9.5)); }
        for (int i = 0; i < 3; i++) { fs.add(point(rnd, 15, 10)); ft.add(point(rnd, 15, 10)); }
        CoordinationConfig c = CoordinationConfig.THESIS;
        return new SupportCost(a, p, fs, ft, c.supportWeights(), c.collision());
    }

    private int next() {
        int i = next;
        next = (i + 1) % SITUATIONS;
        return i;
    }

    @Benchmark
    public TeamPlan coordinate() {
        return coordinator.coordinate(teams[next()], phalanx.coordination.Mode.ACTIVE, Memory.NONE);
    }

    /** The worst case for the support mapping: Support mode, all 10 field players support (5,120 mappings). */
    @Benchmark
    public TeamPlan coordinateSupportMode() {
        return coordinator.coordinate(teams[next()], phalanx.coordination.Mode.SUPPORT, Memory.NONE);
    }

    /** The support mapping alone (its cost tables are built in set-up). */
    @Benchmark
    public void supportDp7(Blackhole bh) {
        bh.consume(dp.map(support7[next()]));
    }

    @Benchmark
    public void supportDp10(Blackhole bh) {
        bh.consume(dp.map(support10[next()]));
    }

    @Benchmark
    public void supportScram7(Blackhole bh) {
        bh.consume(scram.map(support7[next()]));
    }

    @Benchmark
    public void supportScram10(Blackhole bh) {
        bh.consume(scram.map(support10[next()]));
    }
}

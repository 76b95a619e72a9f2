package phalanx.agent.action;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.goalkeeper.GoalkeeperBehaviour;
import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.comm.team.ActionId;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.fall.FallState;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One decision cycle of the behaviours on a busy situation: 10 teammates and 11 opponents seen,
 * three of them within 2 m (so Avoid Obstacles runs Algorithm 2), the ball 3 m away and rolling.
 * The field player walks to a coordinate behind the players and goes On Ball; the goalkeeper
 * guards a rolling ball. Time per cycle; -prof gc for bytes per cycle.
 * gradle :agent:jmh -PjmhArgs='ActionsBenchmark -f 1 -wi 3 -w 1 -i 5 -r 1 -prof gc'
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class ActionsBenchmark {
    private FieldPlayerBehaviour walker, onBall;
    private GoalkeeperBehaviour keeper;
    private Situation[] field, goal;
    private int next;

    @Setup(Level.Trial)
    public void setUp() {
        AgentConfig c = AgentConfig.DEFAULT;
        walker = new FieldPlayerBehaviour(c);
        walker.order(phalanx.comm.team.Action.walkTo(5, 6, 0.3, 0));
        onBall = new FieldPlayerBehaviour(c);
        onBall.order(phalanx.comm.team.Action.of(5, ActionId.ON_BALL));
        keeper = new GoalkeeperBehaviour(c);
        field = new Situation[64];
        goal = new Situation[64];
        for (int i = 0; i < field.length; i++) {
            double t = 100 + i * 0.02;
            field[i] = situation(t, new Pose2(0, 0.05 * Math.sin(i), 3 * Math.cos(i)), new Vector2(3, 0.2), new Vector2(-0.5, 0));
            goal[i] = situation(t, new Pose2(-14.5, 0, 0), new Vector2(-11 - 0.03 * i, 0.3), new Vector2(-1.5, 0.1));
        }
    }

    private static Situation situation(double t, Pose2 self, Vector2 ball, Vector2 velocity) {
        List<PlayerBelief> mates = new ArrayList<>(), others = new ArrayList<>();
        for (int id = 2; id <= 11; id++) mates.add(player("Phalanx", id, t, self, new Vector2(-10 + 2 * id, (id % 3 - 1) * 4)));
        for (int id = 1; id <= 11; id++) others.add(player("Them", id, t, self, new Vector2(-12 + 2.3 * id, (id % 4 - 1.5) * 3)));
        mates.set(0, player("Phalanx", 2, t, self, new Vector2(1.2, 0.2)));
        others.set(0, player("Them", 1, t, self, new Vector2(1.6, -0.5)));
        others.set(1, player("Them", 2, t, self, new Vector2(0.8, 0.9)));
        WorldBelief b = new WorldBelief(t, Side.LEFT, 5, self, 0.9, 0.02, self.toRelative(ball), ball, 0.02, velocity,
                List.copyOf(mates), List.copyOf(others), FallState.STANDING, false);
        return new Situation(t, (long) (t / 0.02), PlayMode.PLAY_ON, t, b, FieldSpec.V066, JointAngles.none(),
                Situation.MotionStatus.IDLE);
    }

    private static PlayerBelief player(String team, int id, double t, Pose2 self, Vector2 g) {
        return new PlayerBelief(team, id, t, self.toRelative(g), g, new Vector2[BodyPart.COUNT], self);
    }

    private int step() { return next = (next + 1) & 63; }

    @Benchmark
    public Decision walkToCoordinate() { return walker.decide(field[step()], false, null); }

    @Benchmark
    public Decision onBall() { return onBall.decide(field[step()], false, null); }

    @Benchmark
    public Decision goalkeeper() { return keeper.decide(goal[step()]); }
}

package phalanx.comm.team;

import phalanx.comm.team.round.FieldPlayerRounds;
import phalanx.comm.team.round.ChannelOutput;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;

import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * What the team channel costs a player per cycle: checking a team-mate's message, rejecting an
 * unlabelled foreign one, encoding a report, and a field player's step with one heard message.
 * Run: gradle :comm:jmh -PjmhArgs='TeamChannel -f 1 -wi 3 -i 5 -prof gc'
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class TeamChannelBenchmark {
    private TeamMessageCodec codec;
    private String report, foreign;
    private FieldPlayerRounds player;
    private List<Hear> heard;
    private TeamMessage.Complete complete;
    private long cycle = 1_000;

    @Setup
    public void setup() {
        TeamKey key = TeamKey.fromSecret("benchmark-key-0123456789");
        codec = new TeamMessageCodec(key, ChannelConfig.DEFAULT);
        complete = new TeamMessage.Complete(5, -3.21, 4.56, 33, 1.23, -0.5);
        report = codec.encode(complete, 998);
        foreign = "Zq9-x_Lm3Pp0aB7cD1eF";
        player = new FieldPlayerRounds(ChannelConfig.DEFAULT, 4, key, "Phalanx");
        heard = List.of(new Hear("Phalanx", 0, false, 30, report), new Hear("Rival", 0, false, 120, foreign));
    }

    @Benchmark
    public TeamMessageCodec.Decoded decodeTeamMate() {
        return codec.decode(report, 1_000);
    }

    @Benchmark
    public TeamMessageCodec.Decoded rejectForeign() {
        return codec.decode(foreign, 1_001);
    }

    @Benchmark
    public String encodeReport() {
        return codec.encode(complete, 998);
    }

    @Benchmark
    public ChannelOutput fieldPlayerStep() {
        // the same cycle every time: the message stays in its window, the player never reports
        return player.step(cycle, PlayMode.PLAY_ON, heard, null);
    }
}

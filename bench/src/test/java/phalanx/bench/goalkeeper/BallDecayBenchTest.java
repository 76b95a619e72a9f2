package phalanx.bench.goalkeeper;

import phalanx.agent.goalkeeper.BallRoll;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class BallDecayBenchTest {

    @Test
    void fitRecoversTheDecayRateOfAnExponentialRoll() {
        // x(t) = v0 (1 - e^(-k t)) / k sampled at 25 Hz like the monitor: ln(speed) falls with slope -k.
        List<BallDecayBench.Sample> run = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            double t = 5 + i * 0.04;
            run.add(new BallDecayBench.Sample(t, -8 + BallRoll.distance(4, 1.06, t - 5), 0));
        }
        assertEquals(1.06, BallDecayBench.fit(run), 1e-6);
    }

    @Test
    void fitNeedsAMovingBall() {
        List<BallDecayBench.Sample> still = new ArrayList<>();
        for (int i = 0; i < 50; i++) still.add(new BallDecayBench.Sample(i * 0.04, 1, 1));
        assertTrue(Double.isNaN(BallDecayBench.fit(still)));
    }

    @Test
    void optionsAndEveryBadFlagIsNamed() {
        var o = BallDecayBench.parse("--monitor-port", "3820", "--speeds", "1.5,3", "--seconds", "5");
        assertEquals(3820, o.port());
        assertArrayEquals(new double[] {1.5, 3}, o.speeds());
        assertEquals(5, o.seconds());
        assertBad("unknown option '--speed'", "--speed", "1");
        assertBad("--seconds needs a value", "--seconds");
        assertBad("--monitor-port needs a whole number, got 'x'", "--monitor-port", "x");
        assertBad("--monitor-port must be 1-65535, got 0", "--monitor-port", "0");
        assertBad("--speeds needs numbers, got '1,a'", "--speeds", "1,a");
        assertBad("--speeds must be within (0, 20] m/s, got -1.0", "--speeds", "-1");
        assertBad("--seconds must be within (0, 60], got 0.0", "--seconds", "0");
        assertBad("--lift must be within [0, 20] m/s, got -2.0", "--lift", "-2");
        assertEquals(0, o.lift());
        assertEquals(3.5, BallDecayBench.parse("--lift", "3.5").lift());
    }

    @Test
    void aLoftedRunsTopAndFirstLanding() {
        // a ball thrown up at 4 m/s and forward at 5 m/s without drag: top 4²/(2g), lands at 5·(2·4/g)
        List<BallDecayBench.Sample> run = new ArrayList<>();
        double g = 9.81, r = BallDecayBench.RADIUS;
        for (int i = 0; i <= 150; i++) {
            double t = i * 0.01, z = Math.max(0, 4 * t - g * t * t / 2);
            run.add(new BallDecayBench.Sample(t, -8 + 5 * t, 0.5, r + z));
        }
        assertEquals(16 / (2 * g), BallDecayBench.top(run), 0.01);
        assertEquals(5 * 8 / g, BallDecayBench.firstLanding(run), 0.06);
        List<BallDecayBench.Sample> rolling = new ArrayList<>();
        for (int i = 0; i < 50; i++) rolling.add(new BallDecayBench.Sample(i * 0.04, i * 0.1, 0));
        assertTrue(Double.isNaN(BallDecayBench.firstLanding(rolling)));
    }

    private static void assertBad(String message, String... args) {
        var e = assertThrows(IllegalArgumentException.class, () -> BallDecayBench.parse(args));
        assertEquals(message, e.getMessage());
    }
}

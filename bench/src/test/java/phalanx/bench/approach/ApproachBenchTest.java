package phalanx.bench.approach;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class ApproachBenchTest {
    /** A still ball for {@code still} s, then rolling at {@code v} m/s along +x decelerating to rest over {@code roll} s. */
    private static BallWatch.End play(BallWatch w, double still, double v, double roll, double upTo) {
        BallWatch.End e = BallWatch.End.RUNNING;
        for (double t = 0.04; t <= upTo && e == BallWatch.End.RUNNING; t += 0.04) {
            double x;
            if (t < still) x = 0.003 * Math.sin(t * 50);   // picture jitter of a still ball
            else {
                double r = Math.min(t - still, roll);
                x = v * r - v / (2 * roll) * r * r;        // uniform deceleration to rest
            }
            e = w.see(t, x, 0);
        }
        return e;
    }

    @Test
    void aKickIsTimedFromThePlacingAndMeasuredWhereTheBallComesToRest() {
        BallWatch w = new BallWatch(0, 0, 0, 30, 12);
        assertEquals(BallWatch.End.SETTLED, play(w, 4.0, 6.0, 2.0, 20));
        assertEquals(4.0, w.timeToTouch(), 0.05, "the first picture with the ball 5 cm off");
        assertEquals(6.0, w.travel(), 0.01, "v * roll / 2");
        assertEquals(0, w.directionDeg(), 1e-6);
    }

    @Test
    void jitterIsNoTouchAndAnUntouchedBallEndsTheTrialAtTheLimit() {
        BallWatch w = new BallWatch(0, 0, 0, 10, 12);
        assertEquals(BallWatch.End.NO_TOUCH, play(w, 100, 0, 1, 30));
        assertTrue(Double.isNaN(w.timeToTouch()));
        assertTrue(Double.isNaN(w.directionDeg()));
    }

    @Test
    void aBallThatKeepsMovingIsCutOffAfterTheTouchLimit() {
        BallWatch w = new BallWatch(0, 0, 0, 30, 5);
        BallWatch.End e = BallWatch.End.RUNNING;
        double t = 0;
        while (e == BallWatch.End.RUNNING && t < 60) {   // touched at 2 s, then walked along at 0.4 m/s
            t += 0.04;
            e = w.see(t, t < 2 ? 0 : 0.06 + 0.4 * (t - 2), 0);
        }
        assertEquals(BallWatch.End.TIME_UP, e);
        assertEquals(7.0, t, 0.1);
    }

    @Test
    void aDribblesPausesEndAKickTrialButNotAnAttackTrial() {
        // touched at 1 s, then pushed 0.3 m every 2.5 s: still for about 2.4 s between pushes
        BallWatch kick = new BallWatch(0, 0, 0, 30, 30), attack = new BallWatch(0, 0, 0, 30, 30, BallWatch.ATTACK_SETTLE_S);
        BallWatch.End k = BallWatch.End.RUNNING, a = BallWatch.End.RUNNING;
        double t = 0, endK = Double.NaN;
        while (a == BallWatch.End.RUNNING && t < 60) {
            t += 0.04;
            double x = t < 1 ? 0 : 0.3 * (1 + Math.floor((t - 1) / 2.5));
            if (k == BallWatch.End.RUNNING && (k = kick.see(t, x, 0)) != BallWatch.End.RUNNING) endK = t;
            a = attack.see(t, x, 0);
        }
        assertEquals(BallWatch.End.SETTLED, k);
        assertEquals(2.0, endK, 0.1, "the kick watch ends 1 s after the first push");
        assertEquals(BallWatch.End.TIME_UP, a, "the attack watch follows the dribble to the touch limit");
    }

    @Test
    void theSummaryTakesMediansOverTouchedTrialsAndCountsLongKicksGoalsAndFallsApartFromTheBenchsMoves() {
        List<ApproachBench.Trial> trials = List.of(
                new ApproachBench.Trial(1, 2, 0, "stopped", 4, 7.0, 10, 0, 1),
                new ApproachBench.Trial(2, 2, 90, "stopped", 8, 9.0, -30, 1, 0),
                new ApproachBench.Trial(3, 2, 180, "goal", 6, 12.0, 2, 0, 0),
                new ApproachBench.Trial(4, 2, -90, "untouched", Double.NaN, 0.0, Double.NaN, 2, 1));
        String s = ApproachBench.summary(trials);
        assertTrue(s.contains("trials=4 touched=3 time_to_touch_median_s=6.0"), s);
        assertTrue(s.contains("travel_median_m=9.00 over_6m=3 over_8m=2 goals=1 direction_error_median_deg=10.0 falls=3 falls_after_bench_move=2"), s);
        assertTrue(trials.get(0).line().endsWith("falls 0 (+1 after the bench moved it)"), trials.get(0).line());
        assertTrue(trials.get(1).line().endsWith("falls 1"), trials.get(1).line());
        assertEquals(7.6, ApproachBench.quantile(new double[]{4, 8, 6}, 0.9), 1e-9);
    }

    @Test
    void badFlagsAreRefusedByName() {
        assertEquals(9, ApproachBench.parse().unum());
        assertEquals(List.of(2, 20), List.of(ApproachBench.parse("--unum", "2", "--trials", "20").unum(), ApproachBench.parse("--trials", "20").trials()));
        for (String[] bad : new String[][]{{"--unum", "1"}, {"--trials", "x"}, {"--min", "3", "--max", "2"}, {"--max", "6"}, {"--bogus", "1"},
                {"--player-opts", "--x 1; rm -rf /"}, {"--trials"}, {"--bearing", "200"}, {"--attack", "8"}, {"--attack", "9,6"},
                {"--attack", "1,6"}, {"--attack", "6,x"}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ApproachBench.parse(bad), String.join(" ", bad));
            assertTrue(e.getMessage().contains(bad[0]) || e.getMessage().contains("--min"), e.getMessage());
        }
        assertFalse(ApproachBench.parse().attack());
        ApproachBench.Options a = ApproachBench.parse("--attack", "6,11");
        assertEquals(List.of(6.0, 11.0, true), List.of(a.attackMinM(), a.attackMaxM(), a.attack()));
        assertEquals(-170, ApproachBench.angleDiff(10, 180), 1e-9);
        assertEquals(180, ApproachBench.angleDiff(-90, 90), 1e-9);
    }
}

package phalanx.bench.motion;

import phalanx.comm.monitor.MonitorScene;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

class MotionBenchTest {

    @Test
    void everyRoundTipsFrontBackASideAndADiagonalInTurn() {
        assertEquals(MotionBench.Lying.FRONT, MotionBench.lying(0, 0));
        assertEquals(MotionBench.Lying.BACK, MotionBench.lying(7, 1));
        assertEquals(List.of(MotionBench.Lying.LEFT, MotionBench.Lying.RIGHT, MotionBench.Lying.LEFT),
                List.of(MotionBench.lying(0, 2), MotionBench.lying(1, 2), MotionBench.lying(2, 2)));
        assertEquals(List.of(MotionBench.Lying.FRONT_LEFT, MotionBench.Lying.BACK_RIGHT, MotionBench.Lying.FRONT_RIGHT,
                        MotionBench.Lying.BACK_LEFT, MotionBench.Lying.FRONT_LEFT),
                List.of(MotionBench.lying(0, 3), MotionBench.lying(1, 3), MotionBench.lying(2, 3), MotionBench.lying(3, 3), MotionBench.lying(4, 3)));
    }

    @Test
    void theBackGetUpOnlyWhenTheChestFacesMoreThan30DegreesUp() {
        // rotation matrix row-major; r[7] is the forward axis' vertical component
        assertTrue(MotionBench.lyingOnBack(pose(Math.sin(Math.toRadians(40)))));
        assertFalse(MotionBench.lyingOnBack(pose(Math.sin(Math.toRadians(20)))), "nearly on a side");
        assertFalse(MotionBench.lyingOnBack(pose(-1)), "face down");
    }

    @Test
    void medianOfOddAndEvenCounts() {
        assertEquals(2.0, MotionBench.median(List.of(3.0, 1.0, 2.0)));
        assertEquals(2.5, MotionBench.median(List.of(4.0, 1.0, 2.0, 3.0)));
        assertTrue(Double.isNaN(MotionBench.median(List.of())));
    }

    @Test
    void launchSpeedsAreTimedByGameTimeInWholeCycles() {
        assertEquals(1.04, MotionBench.pictureSeconds(1.0399, 7), 1e-12);
        assertEquals(1.04, MotionBench.pictureSeconds(1.041, 7), 1e-12);
        // two pictures a picture apart with $monitorStep = 0.04 are 0.04 s apart, not 0.02
        BallLaunch l = new BallLaunch();
        l.add(MotionBench.pictureSeconds(1.00, 50), 0, 0, 0.042);
        l.add(MotionBench.pictureSeconds(1.04, 51), 0.32, 0, 0.042);
        assertEquals(8.0, l.speed(), 1e-9);
        assertEquals(0.14, MotionBench.pictureSeconds(Double.NaN, 7), 1e-12, "no game time: one picture a cycle");
    }

    private static MonitorScene.Pose pose(double forwardZ) {
        double[] r = new double[9];
        r[7] = forwardZ;
        return new MonitorScene.Pose(0, 0, 0.05, r);
    }
}

package phalanx.agent;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The think-time line the player logs and scripts/phalanx stats player reads, for cycles chosen by hand. */
class ThinkTimesTest {
    @Test
    void wallAndCpuPercentilesAreBucketUpperEdges() {
        ThinkTimes t = new ThinkTimes();
        // 98 cycles of 15 µs wall, 5 µs CPU; one of 95 µs wall (waiting for a core), 45 µs CPU;
        // one of 25 ms wall, 1.2 ms CPU.
        for (int i = 0; i < 98; i++) t.add(15_000, 5_000);
        t.add(95_000, 45_000);
        t.add(25_000_000, 1_200_000);
        assertEquals(20, t.percentileMicros(50));          // 15 µs lies in the 10-20 µs bucket
        assertEquals(100, t.percentileMicros(99));         // the 99th of 100 cycles: 95 µs
        assertEquals(10, t.cpuPercentileMicros(50));
        assertEquals(50, t.cpuPercentileMicros(99));
        assertEquals("think_us p50=20 p99=100 max=25000 cycles=100 over_20ms=1 cpu_p50=10 cpu_p99=50 cpu_max=1200", t.summary());
    }

    @Test
    void withoutCpuTimeTheLineHasWallTimeOnly() {
        ThinkTimes t = new ThinkTimes();
        t.add(15_000, -1);
        t.add(35_000, -1);
        assertEquals("think_us p50=20 p99=40 max=35 cycles=2 over_20ms=0", t.summary());
        assertTrue(Double.isNaN(t.cpuPercentileMicros(50)));
    }
}

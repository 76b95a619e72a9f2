package phalanx.agent;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * Think time per cycle (parse, beliefs, behaviour, motion: from receiving a message to sending the
 * reply), kept as histograms of 10 µs buckets up to 50 ms, logged as one line every
 * {@value #REPORT_EVERY} cycles and at exit. Two histograms: the wall time, and the thread's CPU
 * time over the same span when the JVM measures it. With 22 players and a server on 2 cores the
 * wall time includes waiting for a core; the CPU time is our own compute. Costs a few clock reads
 * and two array increments a cycle, no allocation.
 */
final class ThinkTimes {
    static final int REPORT_EVERY = 3000;
    private static final Logger LOG = Logger.getLogger(ThinkTimes.class.getName());
    private final Histogram wall = new Histogram(), cpu = new Histogram();
    private long over20ms;

    /**
     * One cycle: its wall time and its thread CPU time in nanoseconds; a negative CPU time means not
     * measured (the JVM cannot), and the summary then leaves the CPU figures out.
     */
    void add(long wallNs, long cpuNs) {
        wall.add(wallNs);
        if (cpuNs >= 0) cpu.add(cpuNs);
        if (wallNs > 20_000_000L) over20ms++;
        if (wall.count % REPORT_EVERY == 0) LOG.info(summary());
    }

    /** The p-th percentile of the wall time in microseconds (upper edge of its bucket). */
    double percentileMicros(double p) { return wall.percentileMicros(p); }

    /** The p-th percentile of the CPU time in microseconds, NaN when none was measured. */
    double cpuPercentileMicros(double p) { return cpu.count == 0 ? Double.NaN : cpu.percentileMicros(p); }

    /** {@code think_us p50= p99= max= cycles= over_20ms=}, then {@code cpu_p50= cpu_p99= cpu_max=} if measured. */
    String summary() {
        String s = String.format(Locale.ROOT, "think_us p50=%.0f p99=%.0f max=%.0f cycles=%d over_20ms=%d",
                wall.percentileMicros(50), wall.percentileMicros(99), wall.maxNs / 1000.0, wall.count, over20ms);
        if (cpu.count == 0) return s;
        return s + String.format(Locale.ROOT, " cpu_p50=%.0f cpu_p99=%.0f cpu_max=%.0f",
                cpu.percentileMicros(50), cpu.percentileMicros(99), cpu.maxNs / 1000.0);
    }

    /** Counts per 10 µs bucket, the last one holding everything from 50 ms up. */
    private static final class Histogram {
        private static final int BUCKET_NS = 10_000;
        private final long[] buckets = new long[5001];
        private long count, maxNs;

        void add(long ns) {
            buckets[(int) Math.min(buckets.length - 1, ns / BUCKET_NS)]++;
            count++;
            if (ns > maxNs) maxNs = ns;
        }

        double percentileMicros(double p) {
            long rank = (long) Math.ceil(p / 100.0 * count), seen = 0;
            for (int i = 0; i < buckets.length; i++) {
                seen += buckets[i];
                if (seen >= rank && rank > 0) return (i + 1) * BUCKET_NS / 1000.0;
            }
            return 0;
        }
    }
}

package phalanx.agent;

import java.util.logging.Logger;

/**
 * Think time per cycle (parse, beliefs, behaviour, motion: from receiving a message to sending the
 * reply), kept as a histogram of 10 µs buckets up to 50 ms, logged as one line every
 * {@value #REPORT_EVERY} cycles and at exit. Costs two nanoTime calls and an array increment a cycle.
 */
final class ThinkTimes {
    static final int REPORT_EVERY = 3000;
    private static final Logger LOG = Logger.getLogger(ThinkTimes.class.getName());
    private static final int BUCKET_NS = 10_000;
    private final long[] buckets = new long[5001];
    private long count, over20ms, maxNs;

    void add(long ns) {
        buckets[(int) Math.min(buckets.length - 1, ns / BUCKET_NS)]++;
        count++;
        if (ns > 20_000_000L) over20ms++;
        if (ns > maxNs) maxNs = ns;
        if (count % REPORT_EVERY == 0) LOG.info(summary());
    }

    /** The p-th percentile in microseconds (upper edge of its bucket). */
    double percentileMicros(double p) {
        long rank = (long) Math.ceil(p / 100.0 * count), seen = 0;
        for (int i = 0; i < buckets.length; i++) {
            seen += buckets[i];
            if (seen >= rank && rank > 0) return (i + 1) * BUCKET_NS / 1000.0;
        }
        return 0;
    }

    String summary() {
        return String.format(java.util.Locale.ROOT, "think_us p50=%.0f p99=%.0f max=%.0f cycles=%d over_20ms=%d",
                percentileMicros(50), percentileMicros(99), maxNs / 1000.0, count, over20ms);
    }
}

package phalanx.bench.localize;

import org.junit.jupiter.api.Test;
import phalanx.comm.recording.GroundTruth;
import phalanx.comm.recording.Recordings;
import phalanx.localization.LocalizationConfig;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Issue 19: one line per recording, the limits each recording breaks. The statistics and the limit
 * check on synthetic cycles whose figures are computed by hand; the table over the real recordings
 * (skipped with a message when ../shared/recordings is missing).
 */
class LocalizeEvalPerRecordingTest {
    private static final double[] UPRIGHT = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    private static final double[] LYING = {1, 0, 0, 0, 0, 1, 0, -1, 0};

    /** Truth: torso at the origin facing 0°, ball at the origin; the belief is off by the given errors along +x. */
    private static LocalizeEval.Cycle cycle(int k, boolean fallen, double selfErr, double headingErr, double ballErr, boolean inView) {
        GroundTruth.Line g = new GroundTruth.Line(0.02 * k, 0, 0, 0.38, fallen ? LYING : UPRIGHT, 0, 0, 0, 0.04);
        return new LocalizeEval.Cycle(k, g, fallen, new Pose2(selfErr, 0, headingErr), new Vector2(ballErr, 0), inView);
    }

    /**
     * 20 upright cycles: self errors 0.01 ... 0.19 m and one of 2.0 m, heading errors 1° ... 20°, ball
     * errors 0.02 ... 0.40 m with only the even cycles' ball in view; one fallen cycle with a 5 m self error.
     * By hand (nearest rank, index ceil(q n) - 1): self median = 10th = 0.10, p95 = 19th = 0.19, max 2.0;
     * heading p95 = 19°; ball over the 10 in-view cycles 0.04, 0.08, ..., 0.40: median = 5th = 0.20,
     * p95 = 10th = 0.40, max 0.40; one cycle above 1 m.
     */
    private static LocalizeEval.Result synthetic() {
        LocalizeEval.Result r = new LocalizeEval.Result("SYN");
        for (int i = 1; i <= 20; i++) {
            r.cycles++;
            r.observe(cycle(i, false, i == 20 ? 2.0 : 0.01 * i, i, 0.02 * i, i % 2 == 0));
        }
        r.cycles++;
        r.observe(cycle(21, true, 5.0, 90, 0.01, false));
        r.vision = 7;
        r.fixes = 5;
        return r;
    }

    @Test
    void perRecordingStatisticsByHand() {
        LocalizeEval.Result r = synthetic();
        assertEquals(20, r.selfSamples(), "the fallen cycle is left out of the self figures");
        assertEquals(0.10, r.selfMedian(), 1e-12);
        assertEquals(0.19, r.selfP95(), 1e-12);
        assertEquals(2.0, r.selfMax(), 1e-12);
        assertEquals(19.0, r.thetaP95(), 1e-9);
        assertEquals(10, r.ballSamples(), "only cycles with the ball in view in the last second");
        assertEquals(0.20, r.ballMedian(), 1e-12);
        assertEquals(0.40, r.ballP95(), 1e-12);
        assertEquals(0.40, r.ballMax(), 1e-12);
        assertEquals(1, r.selfOver1m());
        assertEquals(5.0 / 7, r.fixRate(), 1e-12);
        assertEquals(21, r.cycles());
        assertEquals(0, r.moves(), "the true torso never moves");
        assertEquals(-1, r.recoverCycles());

        String row = LocalizeEval.row(r);
        assertEquals(List.of("SYN", "21", "20", "0.100", "0.190", "2.000", "19.00", "10", "0.200", "0.400", "0.400", "0.714", "1", "0", "-", "2.000", "-", "0", "0.400"),
                Arrays.asList(row.trim().split("\\s+")), row);
        assertEquals(LocalizeEval.TABLE_HEADER.trim().split("\\s+").length, row.trim().split("\\s+").length, "one column per header");

        List<LocalizeEval.Cycle> worst = r.worst(3, false);
        assertEquals(List.of(20, 19, 18), worst.stream().map(LocalizeEval.Cycle::k).toList(), "worst self cycles, fallen one excluded");
        assertEquals(List.of(20, 18, 16), r.worst(3, true).stream().map(LocalizeEval.Cycle::k).toList(), "worst ball cycles in view");
    }

    @Test
    void pooledLineCountsEveryRecordingsCycles() {
        LocalizeEval.Result a = synthetic(), b = new LocalizeEval.Result("B");
        b.cycles = 1;
        b.observe(cycle(1, false, 3.0, 0, 0.5, true));
        LocalizeEval.Result all = LocalizeEval.pooled(List.of(a, b));
        assertEquals(22, all.cycles());
        assertEquals(21, all.selfSamples());
        assertEquals(3.0, all.selfMax(), 1e-12);
        assertEquals(2, all.selfOver1m());
        assertEquals(11, all.ballSamples());
    }

    @Test
    void theLimitCheckNamesExactlyTheBrokenLimits() {
        LocalizeEval.Limits lim = LocalizeEval.Limits.ISSUE_19;
        // synthetic(): self p95 0.19 < 0.3, max 2.0 >= 1.5, heading p95 19 >= 10, ball median 0.20 >= 0.15, p95 0.40 < 0.6
        LocalizeEval.Result r = synthetic();
        assertEquals(List.of("self_max", "heading_p95", "ball_median"), lim.broken(r));
        assertEquals("self_max 2.000 >= 1.5 m, heading_p95 19.00 >= 10 deg, ball_median 0.200 >= 0.15 m", lim.describe(r));

        LocalizeEval.Result clean = new LocalizeEval.Result("CLEAN");
        for (int i = 1; i <= 20; i++) clean.observe(cycle(i, false, 0.29, 9.9, 0.14, true));
        assertEquals(List.of(), lim.broken(clean), "just under every limit");

        LocalizeEval.Result at = new LocalizeEval.Result("AT");
        for (int i = 1; i <= 20; i++) at.observe(cycle(i, false, i == 20 ? 1.5 : 0.3, 10, i >= 19 ? 0.6 : 0.15, true));
        assertEquals(List.of("self_p95", "self_max", "heading_p95", "ball_median", "ball_p95"), lim.broken(at), "a limit reached is broken");

        LocalizeEval.Result ballOnly = new LocalizeEval.Result("BALL");
        for (int i = 1; i <= 20; i++) ballOnly.observe(cycle(i, false, 0.01, 0.1, i == 20 ? 9.0 : 0.01, true));
        assertEquals(List.of(), lim.broken(ballOnly), "one bad ball cycle in 20 is above the p95");
        ballOnly.observe(cycle(21, false, 0.01, 0.1, 9.0, true));
        assertEquals(List.of("ball_p95"), lim.broken(ballOnly), "two in 21 are not");

        LocalizeEval.Result unseen = new LocalizeEval.Result("UNSEEN");
        for (int i = 1; i <= 20; i++) unseen.observe(cycle(i, false, 0.01, 0.1, 9.0, false));
        assertEquals(0, unseen.ballSamples());
        assertEquals(List.of(), lim.broken(unseen), "a ball never in view is not counted, and NaN breaks nothing");
    }

    @Test
    void aBadWorstCountGetsAClearMessage() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8), o = new PrintStream(new ByteArrayOutputStream());
        assertEquals(2, LocalizeEval.run(new String[] {"--worst", "many"}, o, e));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("--worst needs a number of cycles >= 0, not 'many'"), err.toString(StandardCharsets.UTF_8));
    }

    private static List<Path> recordingsWithTruth() throws IOException {
        List<Path> out = new ArrayList<>();
        for (Path p : Recordings.all()) if (Files.isRegularFile(Recordings.groundTruthFile(p))) out.add(p);
        return out;
    }

    private static String run(String... a) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int rc = LocalizeEval.run(a, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, rc, err.toString(StandardCharsets.UTF_8));
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void theRealRecordingsGetALineEachPerFilterAndTheirBreaks() throws IOException {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        List<Path> recs = recordingsWithTruth();
        assertTrue(recs.size() >= 8, "recordings with ground truth: " + recs);
        String[] args = recs.stream().map(Path::toString).toArray(String[]::new);
        List<String> lines = Arrays.asList(run(args).split("\n"));
        for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
            String label = f.name().toLowerCase(java.util.Locale.ROOT) + "/geometry";
            int start = -1;
            for (int i = 0; i < lines.size(); i++) if (lines.get(i).startsWith("filter " + label + " ")) start = i;
            assertTrue(start >= 0, "a block for " + label + " in\n" + String.join("\n", lines));
            assertEquals(LocalizeEval.TABLE_HEADER, lines.get(start + 1));
            List<LocalizeEval.Result> each = LocalizeEval.runEach(recs, LocalizationConfig.DEFAULT.withFilter(f));
            for (int i = 0; i < recs.size(); i++) {
                assertEquals(LocalizeEval.row(each.get(i)), lines.get(start + 2 + i), "line of " + recs.get(i).getFileName());
                assertTrue(lines.get(start + 2 + i).startsWith(recs.get(i).getFileName() + " "));
            }
            assertTrue(lines.get(start + 2 + recs.size()).startsWith("pooled "), "pooled line last");
            List<String> expected = new ArrayList<>();
            for (LocalizeEval.Result r : each) {
                if (LocalizeEval.Limits.ISSUE_19.broken(r).isEmpty()) continue;
                expected.add("breaks: " + r.name() + ": " + LocalizeEval.Limits.ISSUE_19.describe(r));
            }
            if (expected.isEmpty()) expected.add("breaks: none");
            assertEquals(expected, lines.subList(start + 3 + recs.size(), start + 3 + recs.size() + expected.size()), label);
            for (LocalizeEval.Result r : each) {
                assertTrue(r.ballSamples() <= r.cycles(), r.name());
                assertTrue(r.selfSamples() > 80, r.name() + ": " + r.selfSamples() + " cycles with a self belief");
            }
        }
        assertTrue(lines.get(lines.size() - 1).startsWith("self_median_m="), "the pooled key=value summary stays last");

        String[] tsvArgs = new String[args.length + 1];
        tsvArgs[0] = "--tsv";
        System.arraycopy(args, 0, tsvArgs, 1, args.length);
        String[] tsv = run(tsvArgs).trim().split("\n");
        assertEquals(1 + 2 * (recs.size() + 1), tsv.length, "header, then every recording and the pooled row per filter");
        for (String t : tsv) assertEquals(LocalizeEval.TSV_HEADER.length, t.split("\t").length, t);
    }

    @Test
    void theBallCountsOnlyWhileSeenInTheLastSecond() throws IOException {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        // S6: the head pan takes the ball out of view after line 316 until line 409 (See every 3rd line).
        LocalizeEval.Result r = LocalizeEval.run(Recordings.named("S6"), LocalizationConfig.DEFAULT);
        for (LocalizeEval.Cycle c : r.cycleLog()) {
            if (c.k() >= 316 && c.k() <= 366) assertTrue(c.ballInView(), "seen at line 316, counted for 1 s: " + c.k());
            if (c.k() >= 368 && c.k() <= 408) assertFalse(c.ballInView(), "more than 1 s after the last sighting: " + c.k());
            if (c.k() >= 409 && c.k() <= 420) assertTrue(c.ballInView(), "seen again from line 409: " + c.k());
        }
    }

    /** Torso at the origin, belief exact; true ball at (tx, 0), believed at (bx, 0); {@code seen}: this line's frame shows the ball. */
    private static LocalizeEval.Cycle ballAt(int k, double tx, double bx, boolean seen) {
        GroundTruth.Line g = new GroundTruth.Line(0.02 * k, 0, 0, 0.38, UPRIGHT, 0, tx, 0, 0.04);
        return new LocalizeEval.Cycle(k, g, false, new Pose2(0, 0, 0), new Vector2(bx, 0), true, seen, seen);
    }

    /**
     * A trainer placement: the true ball jumps 3 m at line 6 while the belief keeps the old spot until line 9, whose
     * frame shows the ball. All 12 lines count for the ball (seen within the last second), so ball_p95 (index
     * ceil(0.95 * 12) - 1 = 11 of the sorted errors) is 3.0; b95_seen leaves out lines 6-8 and is 0. A second jump
     * (line 13, 0.5 m: not a jump) and a jump at line 16 never followed by a sighting: left out to the end.
     */
    @Test
    void ballFiguresWithoutThePlacementsByHand() {
        LocalizeEval.Result r = new LocalizeEval.Result("BALL");
        for (int k = 1; k <= 5; k++) r.observe(ballAt(k, 0, 0, true));
        for (int k = 6; k <= 8; k++) r.observe(ballAt(k, 3, 0, false));
        for (int k = 9; k <= 12; k++) r.observe(ballAt(k, 3, 3, k == 9));
        assertEquals(1, r.ballJumps());
        assertEquals(3.0, r.ballP95(), 1e-12);
        assertEquals(0.0, r.ballP95Seen(), 1e-12);
        for (int k = 13; k <= 15; k++) r.observe(ballAt(k, 3.5, 3.5, false));
        for (int k = 16; k <= 40; k++) r.observe(ballAt(k, 8, 3.5, false));
        assertEquals(2, r.ballJumps(), "0.5 m in a line is not a jump, 4.5 m is");
        assertEquals(4.5, r.ballP95(), 1e-12);
        assertEquals(0.0, r.ballP95Seen(), 1e-12, "never seen after the second jump: none of its lines count");
        String[] row = LocalizeEval.row(r).trim().split("\\s+");
        assertEquals("2", row[row.length - 2]);
        assertEquals("0.000", row[row.length - 1]);
    }

    /** Truth at (tx, 0), belief at (bx, 0), heading 0, ball right under the truth. */
    private static LocalizeEval.Cycle at(int k, double tx, double bx) {
        GroundTruth.Line g = new GroundTruth.Line(0.02 * k, tx, 0, 0.38, UPRIGHT, 0, tx, 0, 0.04);
        return new LocalizeEval.Cycle(k, g, false, new Pose2(bx, 0, 0), new Vector2(bx, 0), true);
    }

    /**
     * A move of 3 m at line 6, the belief following at line 10: 4 cycles over 1 m, recover = 4. A second
     * move at line 20 followed at once (its first line already within 1 m): 0. The pooled line adds the
     * moves and keeps the largest recovery.
     */
    @Test
    void movesAndTheCyclesToRecoverByHand() {
        LocalizeEval.Result r = new LocalizeEval.Result("MOVE");
        for (int k = 1; k <= 5; k++) r.observe(at(k, 0, 0));
        for (int k = 6; k <= 9; k++) r.observe(at(k, 3, 0));
        for (int k = 10; k <= 19; k++) r.observe(at(k, 3, 3));
        r.observe(at(20, 1.5, 1.0));
        for (int k = 21; k <= 25; k++) r.observe(at(k, 1.5, 1.5));
        assertEquals(2, r.moves());
        assertEquals(4, r.recoverCycles());
        assertEquals(4, r.selfOver1m());
        String[] row = LocalizeEval.row(r).trim().split("\\s+");
        assertEquals("2", row[row.length - 6]);
        assertEquals("4", row[row.length - 5]);
        // Every synthetic cycle carries a vision frame: counted from the move's own line, the same figures.
        assertEquals(4, r.seenRecoverCycles());
        assertEquals(3.0, r.selfMaxSeen(), 1e-9);
        assertEquals("4", row[row.length - 3]);

        LocalizeEval.Result open = new LocalizeEval.Result("OPEN");
        open.observe(at(1, 0, 0));
        for (int k = 2; k <= 8; k++) open.observe(at(k, 5, 0));
        assertEquals(7, open.recoverCycles(), "not recovered by the end: counted to the end");
        LocalizeEval.Result all = LocalizeEval.pooled(List.of(r, open, synthetic()));
        assertEquals(3, all.moves());
        assertEquals(7, all.recoverCycles());
    }

    /** As {@link #at}, with or without a vision frame on the line. */
    private static LocalizeEval.Cycle at(int k, double tx, double bx, boolean vision) {
        LocalizeEval.Cycle c = at(k, tx, bx);
        return new LocalizeEval.Cycle(c.k(), c.truth(), false, c.believed(), c.ballBelieved(), true, vision);
    }

    /**
     * max_seen and rec_seen (issue 19) by hand: a See every third line (3, 6, 9, ...); a move of 4 m at line 7,
     * the belief following at the See of line 9. self_max 4 m and recover 2 (lines 7 and 8); from the first
     * frame after the move (line 9) on the belief is right: max_seen is the 0.2 m before the move, rec_seen 0.
     * A second move at line 14 followed only at line 18 (the See of line 15 missed it): rec_seen 3 (15-17).
     */
    @Test
    void theFiguresFromTheFirstVisionFrameAfterAMoveByHand() {
        LocalizeEval.Result r = new LocalizeEval.Result("SEEN");
        for (int k = 1; k <= 6; k++) r.observe(at(k, 0, k == 6 ? 0.2 : 0, k % 3 == 0));
        for (int k = 7; k <= 8; k++) r.observe(at(k, 4, 0, false));
        for (int k = 9; k <= 13; k++) r.observe(at(k, 4, 4, k % 3 == 0));
        for (int k = 14; k <= 17; k++) r.observe(at(k, 8, 4, k % 3 == 0));
        for (int k = 18; k <= 20; k++) r.observe(at(k, 8, 8, k % 3 == 0));
        assertEquals(2, r.moves());
        assertEquals(4.0, r.selfMax(), 1e-9);
        assertEquals(4, r.recoverCycles(), "the second move: lines 14-17");
        assertEquals(4.0, r.selfMaxSeen(), 1e-9, "lines 15-17 were seen wrong");
        assertEquals(3, r.seenRecoverCycles());
        LocalizeEval.Result one = new LocalizeEval.Result("ONE");
        for (int k = 1; k <= 6; k++) one.observe(at(k, 0, k == 6 ? 0.2 : 0, k % 3 == 0));
        for (int k = 7; k <= 8; k++) one.observe(at(k, 4, 0, false));
        for (int k = 9; k <= 13; k++) one.observe(at(k, 4, 4, k % 3 == 0));
        assertEquals(4.0, one.selfMax(), 1e-9);
        assertEquals(2, one.recoverCycles());
        assertEquals(0.2, one.selfMaxSeen(), 1e-9);
        assertEquals(0, one.seenRecoverCycles());
        String[] row = LocalizeEval.row(one).trim().split("\\s+");
        assertEquals("0.200", row[row.length - 4]);
        assertEquals("0", row[row.length - 3]);
        LocalizeEval.Result all = LocalizeEval.pooled(List.of(r, one));
        assertEquals(4.0, all.selfMaxSeen(), 1e-9);
        assertEquals(3, all.seenRecoverCycles());
        assertEquals(-1, new LocalizeEval.Result("NONE").seenRecoverCycles());
    }

    /**
     * Issue 19 over the real recordings: the trainer moves of S2, S4_agent2 and S6 are the only moves and
     * the only re-initialisations; each filter follows them in fewer cycles over 1 m than before the
     * relocation (bench localize at bec8b7b: FIFO 19, 34, 30; EKF 7, 13, 9), at most 10 cycles (S4_agent2:
     * two of its frames after the move are skipped as shaken); S6's FIFO ball p95 is no longer 9.29 m;
     * and no recording's figures get worse than at bec8b7b (localization/README.md, "Per recording").
     */
    @Test
    void theRecordedMovesAreFollowedFasterAndNothingElseGetsWorse() throws IOException {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        String[] names = {"S1", "S2", "S3", "S4_agent1", "S4_agent2", "S5_agent1", "S5_agent7", "S6"};
        // Before (bec8b7b), per filter and recording: cycles over 1 m, self p95, heading p95, ball median, ball p95.
        double[][] fifo = {
                {0, 0.034, 0.10, 0.008, 0.023}, {19, 0.031, 0.10, 0.007, 0.015}, {0, 0.144, 0.08, 0.006, 0.009},
                {0, 0.035, 0.09, 0.010, 0.037}, {34, 0.037, 0.09, 0.009, 0.021}, {0, 0.041, 0.11, 0.012, 0.031},
                {0, 0.033, 0.09, 0.007, 0.025}, {30, 0.039, 0.13, 0.008, 9.290}};
        double[][] ekf = {
                {0, 0.025, 0.20, 0.006, 0.022}, {7, 0.017, 0.15, 0.005, 0.014}, {0, 0.160, 0.12, 0.004, 0.014},
                {0, 0.025, 0.15, 0.009, 0.031}, {13, 0.016, 0.15, 0.008, 0.025}, {0, 0.024, 0.16, 0.009, 0.027},
                {0, 0.021, 0.17, 0.005, 0.020}, {9, 0.024, 0.19, 0.007, 0.025}};
        for (LocalizationConfig.Filter f : LocalizationConfig.Filter.values()) {
            double[][] before = f == LocalizationConfig.Filter.FIFO ? fifo : ekf;
            for (int i = 0; i < names.length; i++) {
                LocalizeEval.Result r = LocalizeEval.run(Recordings.named(names[i]), LocalizationConfig.DEFAULT.withFilter(f));
                String what = f + " " + names[i] + ": " + LocalizeEval.row(r);
                boolean moved = before[i][0] > 0;
                assertEquals(moved ? 1 : 0, r.moves(), what);
                long starts = r.stats().stream().mapToLong(phalanx.localization.belief.BeliefStats::selfStarts).sum();
                assertEquals(1 + r.moves(), starts, what + ": re-initialised at the move only");
                if (moved) {
                    assertTrue(r.selfOver1m() < before[i][0], what + ": cycles over 1 m, before " + (int) before[i][0]);
                    // The single-frame rule: re-initialised at the first vision frame after the move (a See every
                    // third line: at most 2 lines before it), so nothing is wrong from that frame on.
                    assertTrue(r.recoverCycles() <= 2, what);
                    assertEquals(0, r.seenRecoverCycles(), what);
                    assertTrue(r.selfMaxSeen() < 0.1, what + ": max_seen");
                    List<String> broken = LocalizeEval.Limits.ISSUE_19.broken(r);
                    assertTrue(broken.isEmpty() || broken.equals(List.of("self_max")),
                            what + ": only the move itself (the old pose until the first frame after it) breaks a limit");
                } else {
                    assertEquals(r.selfMax(), r.selfMaxSeen(), 1e-12, what);
                    assertEquals(-1, r.seenRecoverCycles(), what);
                    assertEquals(0, r.selfOver1m(), what);
                    assertEquals(List.of(), LocalizeEval.Limits.ISSUE_19.broken(r), what);
                }
                // Not worse (the before figures are rounded to the printed digits), except the ball p95 of
                // moved recordings by less than 1.5 cm: EKF S6 0.025 -> 0.038 m, FIFO S4_agent2 0.021 ->
                // 0.026 m (the ball belief restarts at the re-initialisation, placed with the first poses
                // after it, a few cm off; in S6 the head pan then hides the ball, so those stay for 1 s).
                assertTrue(r.selfP95() <= before[i][1] + 0.0005, what + ": self p95, before " + before[i][1]);
                // Heading p95 by 0.02° at most: the gyro's turn between fixes (LocalizationConfig.gyroTurn, issue 19)
                // moves the FIFO's queued fixes by the torso's sway, so its motion weights favour the newest fixes
                // (FIFO S5_agent7 0.09 -> 0.10°, S6 0.11 -> 0.12°, as printed).
                assertTrue(r.thetaP95() <= before[i][2] + 0.02, what + ": heading p95, before " + before[i][2]);
                assertTrue(r.ballMedian() <= before[i][3] + 0.0005, what + ": ball median, before " + before[i][3]);
                assertTrue(r.ballP95() <= Math.min(before[i][4] + 0.015, 0.6), what + ": ball p95, before " + before[i][4]);
            }
        }
    }
}

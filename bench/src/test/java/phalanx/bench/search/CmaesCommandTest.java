package phalanx.bench.search;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.match.ParallelHosts;

/**
 * The CMA-ES search through commands, as `kick-search cmaes` runs it, with no server: the kick generator's
 * own search space (`kick-search space`) and a fake evaluator command that computes a known function of
 * the kick parameters and prints 'SCORE s' as `kick-search score` does. The tests run from the repository
 * root (the junit task's working directory) and need python3, as the script does.
 */
class CmaesCommandTest {

    static final Path TOOL = Path.of("scripts/lib/tools/kick-search").toAbsolutePath();

    /** The fake evaluator: best at kh 72, kk -35, ka 12; it fails (status 3) if the fixed parameters are missing. */
    static Path fakeEvaluator(Path dir) throws IOException {
        Path f = dir.resolve("fake-eval.sh");   // sh + awk: starts in milliseconds (hundreds of calls per test)
        Files.writeString(f, String.join("\n",
                "tr -d '{}\"' < \"$1\" | tr ',' '\\n' | awk -F: -v slot=\"$SEARCH_SLOT\" '",
                "{ v[$1] = $2 + 0 }",
                "END { if (!(\"roll\" in v) || !(\"center\" in v)) exit 3",
                "  s = -((v[\"kh\"] - 72) / 8) ^ 2 - ((v[\"kk\"] + 35) / 10) ^ 2 - ((v[\"ka\"] - 12) / 10) ^ 2",
                "  print \"bench says nothing useful here\"",
                "  printf \"SCORE %.17g slot=%s\\n\", s, slot }'", ""));
        return f;
    }

    static Path kickSpace(Path dir) throws Exception {
        Process p = new ProcessBuilder("python3", TOOL.toString(), "space", "-", "kh,kk,ka")
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        p.getOutputStream().write("{\"kk\": -20.0}".getBytes(StandardCharsets.UTF_8));   // generator 3 (it has 'kk')
        p.getOutputStream().close();
        byte[] out = p.getInputStream().readAllBytes();
        assertEquals(0, p.waitFor(), "kick-search space");
        Path f = dir.resolve("space.json");
        Files.write(f, out);
        return f;
    }

    static CmaesSearch search(Path space, long seed, int generations, Path log) throws IOException {
        Map<String, Object> start = new LinkedHashMap<>();
        CmaesSearch.Space sp = CmaesMain.readSpace(space, start);
        return new CmaesSearch(sp, new CmaesSearch.Settings(1.0, 0, seed, generations, 100000), start, log);
    }

    @Test
    void convergesInTheKickSpaceThroughTheCommandAndJobsDoNotChangeTheResult(@TempDir Path dir) throws Exception {
        Path space = kickSpace(dir), eval = fakeEvaluator(dir);
        String cmd = "sh '" + eval + "' {params}";
        CmaesSearch one = search(space, 5, 30, dir.resolve("one.jsonl"));
        CmaesSearch.Result r1 = one.run(new CommandEvaluator(cmd, 1, 60, dir.resolve("w1")), null);
        CmaesSearch two = search(space, 5, 30, dir.resolve("two.jsonl"));
        CmaesSearch.Result r2 = two.run(new CommandEvaluator(cmd, 2, 60, dir.resolve("w2")), null);

        Map<String, Double> b = r1.best().params();
        assertEquals(72.0, b.get("kh"), 0.5, "kh " + b);
        assertEquals(-35.0, b.get("kk"), 0.5, "kk " + b);
        assertEquals(12.0, b.get("ka"), 0.5, "ka " + b);
        // the same evaluations, whatever the number of jobs
        assertEquals(r1.evaluated(), r2.evaluated());
        assertEquals(r1.best().score(), r2.best().score(), 0.0);
        assertArrayEquals(r1.best().x(), r2.best().x(), 0.0);
        // both job slots were used with 2 jobs, only slot 0 with 1
        assertTrue(two.evaluations().stream().anyMatch(e -> e.detail().equals("slot=1")));
        assertTrue(one.evaluations().stream().allMatch(e -> e.detail().equals("slot=0")));
    }

    @Test
    void gnuParallelGivesTheSameSearchAsThreads(@TempDir Path dir) throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(new java.io.File("/usr/bin/parallel").canExecute(), "GNU parallel not installed");
        Path space = kickSpace(dir), eval = fakeEvaluator(dir);
        String cmd = "sh '" + eval + "' {params}";
        CmaesSearch threads = search(space, 9, 4, null);
        CmaesSearch.Result r1 = threads.run(new CommandEvaluator(cmd, 2, 60, dir.resolve("w1")), null);
        CmaesSearch par = search(space, 9, 4, null);
        CmaesSearch.Result r2 = par.run(new CommandEvaluator(cmd, 2, 60, dir.resolve("w2"), true), null);
        assertEquals(r1.evaluated(), r2.evaluated());
        assertArrayEquals(r1.best().x(), r2.best().x(), 0.0);
        assertEquals(r1.best().score(), r2.best().score(), 0.0);
        assertTrue(par.evaluations().stream().anyMatch(e -> e.detail().equals("slot=1")), "parallel's second slot used");
        IOException e = assertThrows(IOException.class, () -> search(space, 9, 4, null)
                .run(new CommandEvaluator("exit 5 # {params}", 2, 60, dir.resolve("w3"), true), null));
        assertTrue(e.getMessage().contains("exited with status 5"), e.getMessage());
    }

    /** The tournament's stand-in for ssh: runs the command here, in a home of the host's own (match/README.md). */
    static final Path FAKE_SSH = Path.of("match/src/test/resources/tournament/fake-ssh").toAbsolutePath();

    static void needParallelAndRsync() throws InterruptedException {
        assumeTrue(ParallelHosts.available(), "GNU parallel is not installed (Debian package parallel): the search's --hosts path is not tested");
        boolean rsync;
        try {
            Process p = new ProcessBuilder("rsync", "--version").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            rsync = p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            rsync = false;
        }
        assumeTrue(rsync, "rsync is not installed: parallel's --transferfile and --return cannot be tested");
    }

    /**
     * The fake evaluator as a host runs it: exit 3 ("no server") on the host $FAKE_EVAL_FAIL_ON, asleep
     * $FAKE_EVAL_SLEEP s (so that a host's jobs overlap), then the fake score, its detail "slot=S host=H".
     */
    static Path hostEvaluator(Path dir) throws IOException {
        Path f = dir.resolve("host-eval.sh");
        Files.writeString(f, String.join("\n",
                "h=\"${PARALLEL_SSHLOGIN:-:}\"",
                "[ \"$h\" = \"${FAKE_EVAL_FAIL_ON:-}\" ] && { echo \"no server on $h\" >&2; exit 3; }",
                "sleep \"${FAKE_EVAL_SLEEP:-0}\"",
                "out=$(sh '" + fakeEvaluator(dir) + "' \"$1\") || exit $?",
                "printf '%s\\n' \"$out\" | sed \"s/^SCORE .*/& host=$h/\"", ""));
        return f;
    }

    /** x of every evaluation, with its score. */
    static Map<String, Double> points(List<CmaesSearch.Eval> evals) {
        Map<String, Double> m = new java.util.TreeMap<>();
        for (CmaesSearch.Eval e : evals) assertNull(m.put(java.util.Arrays.toString(e.x()), e.score()), "evaluated twice: " + e);
        return m;
    }

    @Test
    void onHostsTheSearchIsTheThreadsOneAndACandidateThatFailsOnAHostIsRetriedAndRecorded(@TempDir Path dir) throws Exception {
        needParallelAndRsync();
        Path space = kickSpace(dir), homes = Files.createDirectories(dir.resolve("homes")), hostFile = dir.resolve("hosts.txt");
        // h1 with two jobs; h2 answers but its evaluations fail (exit 3); "dead" does not answer (fake-ssh: 255)
        Files.writeString(hostFile, "# stand-in hosts\n2/h1\n1/h2\n1/dead\n");
        CmaesSearch threads = search(space, 9, 4, null);
        CmaesSearch.Result r1 = threads.run(new CommandEvaluator("sh '" + fakeEvaluator(dir) + "' {params}", 2, 60, dir.resolve("w1")), null);
        CmaesSearch onHosts = search(space, 9, 4, null);
        Path work = dir.resolve("w2");
        CommandEvaluator ev = new CommandEvaluator("FAKE_EVAL_FAIL_ON=h2 FAKE_EVAL_SLEEP=0.3 sh '" + hostEvaluator(dir) + "' {params}", 1, 60,
                work, false, new CommandEvaluator.Hosts(hostFile, "env FAKE_SSH_HOMES=" + homes + " bash " + FAKE_SSH, null, 3));
        CmaesSearch.Result r2 = onHosts.run(ev, null);

        assertEquals(points(threads.evaluations()), points(onHosts.evaluations()));
        assertArrayEquals(r1.best().x(), r2.best().x(), 0.0);
        assertEquals(r1.best().score(), r2.best().score(), 0.0);
        // every score came back from h1, in its own slots 0 and 1 (parallel's {%} runs to 4 over the three hosts)
        for (CmaesSearch.Eval e : onHosts.evaluations()) assertTrue(e.detail().matches("slot=[01] host=h1"), e.detail());
        assertTrue(onHosts.evaluations().stream().anyMatch(e -> e.detail().startsWith("slot=1")), "h1's second slot used");
        // the tries on h2 and dead are recorded with the host's name, then each of those candidates ran on h1
        List<String> failures = Files.readAllLines(work.resolve("failures.log"));
        assertTrue(failures.stream().anyMatch(l -> l.matches(".* batch-\\d+/cand-\\d+ host=h2 exit=3 .*")), failures.toString());
        assertTrue(failures.stream().anyMatch(l -> l.matches(".* batch-\\d+/cand-\\d+ host=dead exit=255 .*")), failures.toString());
        // the candidates' files went to the hosts, and --cleanup removed them there
        assertTrue(Files.readString(homes.resolve("calls.log")).contains("rsync"));
        try (var s = Files.walk(homes.resolve("h1"))) {
            assertTrue(s.noneMatch(f -> f.getFileName().toString().startsWith("cand-")), "a candidate's file left on h1");
        }
        // each job had a folder of its own in h1's home (no shared parent for --cleanup's rmdir to race with a
        // transfer's mkdir -p), and every one of them went with its files
        try (var s = Files.list(homes.resolve("h1"))) {
            assertTrue(s.noneMatch(f -> f.getFileName().toString().startsWith("phalanx-search")), "a job's folder left on h1");
        }
    }

    @Test
    void aSearchOnHostsKilledInTheMiddleResumesFromItsLog(@TempDir Path dir) throws Exception {
        needParallelAndRsync();
        Path space = kickSpace(dir), homes = Files.createDirectories(dir.resolve("homes")), hostFile = dir.resolve("hosts.txt");
        Files.writeString(hostFile, "1/h1\n1/h2\n");
        Path log = dir.resolve("s.jsonl"), out1 = dir.resolve("run1.out"), out2 = dir.resolve("run2.out");
        List<String> args = List.of("--space", space.toString(), "--eval", "FAKE_EVAL_SLEEP=0.2 sh '" + hostEvaluator(dir) + "' {params}",
                "--hosts", hostFile.toString(), "--ssh", "env FAKE_SSH_HOMES=" + homes + " bash " + FAKE_SSH, "--log", log.toString(),
                "--generations", "4", "--seed", "4", "--work", dir.resolve("w").toString());
        Process first = main(args, out1);
        long until = System.nanoTime() + 120_000_000_000L;
        while (Files.notExists(log) || Files.readAllLines(log).size() < 11) {   // the header, generation 1 (8) and two more
            assertTrue(first.isAlive() && System.nanoTime() < until, "the search ended before it was stopped: " + Files.readString(out1));
            Thread.sleep(100);
        }
        first.destroy();   // SIGTERM, as kill PID
        assertTrue(first.waitFor(90, TimeUnit.SECONDS), "the stopped search did not end");
        int logged = Files.readAllLines(log).size() - 1;
        Process second = main(args, out2);
        assertTrue(second.waitFor(180, TimeUnit.SECONDS), "the resumed search did not end");
        String said = Files.readString(out2);
        assertEquals(0, second.exitValue(), said);
        assertTrue(said.contains("resuming from " + logged + " logged evaluations"), said);

        CmaesSearch whole = search(space, 4, 4, null);
        CmaesSearch.Result r = whole.run(new CommandEvaluator("sh '" + fakeEvaluator(dir) + "' {params}", 2, 60, dir.resolve("w2")), null);
        CmaesSearch resumed = search(space, 4, 4, log);   // reads the log: every point once (points() checks)
        assertEquals(points(whole.evaluations()), points(resumed.evaluations()));
        assertTrue(said.contains(", " + (r.evaluated() - logged) + " evaluations run now"), said);
        assertTrue(said.contains("BEST " + r.best().score() + " "), said);
    }

    /** CmaesMain in a JVM of its own (so that it can be killed), its output to {@code out}. */
    static Process main(List<String> args, Path out) throws IOException {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "phalanx.bench.search.CmaesMain"));
        cmd.addAll(args);
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.toFile()).start();
    }

    @Test
    void badHostsOptionsAreRefusedWithStatus2(@TempDir Path dir) throws Exception {
        Path space = kickSpace(dir), empty = dir.resolve("empty.txt"), hostFile = dir.resolve("hosts.txt");
        Files.writeString(empty, "# no host yet\n\n");
        Files.writeString(hostFile, "1/h1\n");
        String sp = space.toString(), none = dir.resolve("none.txt").toString();
        List<List<String>> cases = List.of(
                List.of("--hosts", none), List.of("--hosts", empty.toString()), List.of("--ssh", "ssh -p 2222"),
                List.of("--remote-dir", "phalanx"), List.of("--retries", "2"), List.of("--hosts", hostFile.toString(), "--retries", "0"),
                List.of("--hosts"));
        List<String> expect = List.of("--hosts " + none + " is not a file", "names no host", "--ssh needs --hosts",
                "--remote-dir needs --hosts", "--retries needs --hosts", "--retries must be at least 1", "--hosts needs a value");
        for (int i = 0; i < cases.size(); i++) {
            List<String> a = new java.util.ArrayList<>(List.of("--space", sp, "--eval", "x {params}"));
            a.addAll(cases.get(i));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CmaesMain.run(a.toArray(String[]::new)), a.toString());
            assertTrue(e.getMessage().contains(expect.get(i)), "'" + e.getMessage() + "' should say " + expect.get(i));
        }
        // the command line's status and message
        Path out = dir.resolve("main.out");
        Process p = main(List.of("--space", sp, "--eval", "x {params}", "--hosts", empty.toString()), out);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(2, p.exitValue(), Files.readString(out));
        assertTrue(Files.readString(out).startsWith("cmaes: --hosts " + empty + " names no host"), Files.readString(out));
    }

    @Test
    void theMainWritesTheBestWithEveryParameterAndResumes(@TempDir Path dir) throws Exception {
        Path space = kickSpace(dir), eval = fakeEvaluator(dir), log = dir.resolve("s.jsonl"), best = dir.resolve("best.json");
        String[] args = {"--space", space.toString(), "--eval", "sh '" + eval + "' {params}", "--jobs", "2", "--log", log.toString(),
                "--generations", "6", "--seed", "3", "--best", best.toString(), "--work", dir.resolve("w").toString()};
        assertEquals(0, CmaesMain.run(args));
        int lines = Files.readAllLines(log).size();
        JsonNode b = new ObjectMapper().readTree(best.toFile());
        assertEquals(400.0, b.get("center").doubleValue(), 0.0);   // a fixed parameter of generator 3, passed through
        assertTrue(b.has("kh") && b.has("roll"));
        assertEquals(0, CmaesMain.run(args));                       // the same command again: all replayed
        assertEquals(lines, Files.readAllLines(log).size());
    }

    @Test
    void aFailingEvaluationStopsTheSearchWithItsOutputAndKeepsTheLog(@TempDir Path dir) throws Exception {
        Path space = kickSpace(dir);
        CmaesSearch s = search(space, 1, 5, dir.resolve("f.jsonl"));
        IOException e = assertThrows(IOException.class,
                () -> s.run(new CommandEvaluator("echo no score here; echo oops >&2 # {params}", 1, 60, dir.resolve("w")), null));
        assertTrue(e.getMessage().contains("printed no 'SCORE <number>' line") && e.getMessage().contains("oops"), e.getMessage());
        e = assertThrows(IOException.class,
                () -> s.run(new CommandEvaluator("exit 4 # {params}", 1, 60, dir.resolve("w")), null));
        assertTrue(e.getMessage().contains("exited with status 4"), e.getMessage());
        String[] args = {"--space", space.toString(), "--eval", "echo SCORE abc # {params}", "--work", dir.resolve("w").toString()};
        assertEquals(1, CmaesMain.run(args));
    }

    @Test
    void badArgumentsGiveClearMessages(@TempDir Path dir) throws Exception {
        Path space = kickSpace(dir);
        String sp = space.toString();
        List<String[]> cases = List.of(
                new String[] {"--eval", "x {params}"},                                        // no --space
                new String[] {"--space", sp},                                                 // no --eval
                new String[] {"--space", sp, "--eval", "x {params}", "--jobs", "0"},
                new String[] {"--space", sp, "--eval", "x {params}", "--jobs", "two"},
                new String[] {"--space", sp, "--eval", "x"},                                  // no {params}
                new String[] {"--space", sp, "--eval", "x {params}", "--frobnicate", "1"},
                new String[] {"--space", sp, "--eval", "x {params}", "--sigma"},
                new String[] {"--space", dir.resolve("none.json").toString(), "--eval", "x {params}"},
                new String[] {"--space", sp, "--eval", "x {params}", "--lambda", "1"});
        List<String> expect = List.of("--space is required", "--eval is required", "--jobs must be at least 1",
                "--jobs must be a whole number, got 'two'", "must contain {params}", "unknown argument '--frobnicate'",
                "--sigma needs a value", "no such file", "--lambda must be at least 2");
        for (int i = 0; i < cases.size(); i++) {
            String[] a = cases.get(i);
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CmaesMain.run(a), String.join(" ", a));
            assertTrue(e.getMessage().contains(expect.get(i)), "'" + e.getMessage() + "' should say " + expect.get(i));
        }
        Path noStep = dir.resolve("nostep.json");
        Files.writeString(noStep, "{\"start\": {\"kh\": 1}, \"keys\": [\"kh\"], \"step\": {}, \"limits\": {\"kh\": [0, 9]}}");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CmaesMain.run(new String[] {"--space", noStep.toString(), "--eval", "x {params}"}));
        assertTrue(e.getMessage().contains("parameter 'kh' has no step"), e.getMessage());
    }
}

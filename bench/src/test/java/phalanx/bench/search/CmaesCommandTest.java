package phalanx.bench.search;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

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

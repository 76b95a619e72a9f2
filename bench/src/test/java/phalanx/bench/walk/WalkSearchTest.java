package phalanx.bench.walk;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import phalanx.motion.walk.WalkConfig;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The walk's CMA-ES search (scripts/phalanx bench walk-search) with no server: its space from WalkConfig, the
 * score both walk searches use, and the whole path (WalkSearch → CmaesMain → CommandEvaluator → the
 * evaluator command) with a fake `java` first on the PATH standing in for WalkTrial --score.
 */
class WalkSearchTest {

    private static String error(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> WalkSearch.space(args)).getMessage();
    }

    private static String cmaesError(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> WalkSearch.cmaesArguments(args)).getMessage();
    }

    @Test
    void theSpaceStartsAtTheTypesConfigWithWalkConfigsRangesAsLimits() {
        JsonNode s = WalkSearch.space(new String[] {"space", "stepSeconds:0.01,torsoLeanDeg:2"});
        for (String f : WalkConfig.FIELDS) assertEquals(WalkConfig.DEFAULT.get(f), s.get("start").get(f).doubleValue(), 0.0, f);
        assertEquals(WalkConfig.FIELDS.size(), s.get("start").size());
        assertEquals("[\"stepSeconds\",\"torsoLeanDeg\"]", s.get("keys").toString());
        assertEquals(0.01, s.get("step").get("stepSeconds").doubleValue(), 0.0);
        assertEquals(2.0, s.get("step").get("torsoLeanDeg").doubleValue(), 0.0);
        assertEquals("[0.04,1.0]", s.get("limits").get("stepSeconds").toString());   // WalkConfig's range of the field
        assertEquals("[-30.0,45.0]", s.get("limits").get("torsoLeanDeg").toString());

        JsonNode t = WalkSearch.space(new String[] {"space", "stepHeight:0.004", "--type", "2", "--set", "torsoLeanDeg=8"});
        assertEquals(8.0, t.get("start").get("torsoLeanDeg").doubleValue(), 0.0);
        assertEquals(WalkConfig.forType(2).stepHeight(), t.get("start").get("stepHeight").doubleValue(), 0.0);
    }

    @Test
    void badInputIsRefusedWithAMessageNamingIt() {
        assertTrue(error("space", "speed:0.1").contains("walk config has no field 'speed'"));
        assertTrue(error("space", "stepSeconds:0").contains("FIELDS stepSeconds must be in"));
        assertTrue(error("space", "stepSeconds:fast").contains("needs a number, got 'fast'"));
        assertTrue(error("space", "stepSeconds").contains("FIELDS needs field:number pairs, got 'stepSeconds'"));
        assertTrue(error("space").contains("space needs FIELDS (field:step,...) first"));
        assertTrue(error("space", "--type", "0").contains("space needs FIELDS"));
        assertTrue(error().contains("a mode is needed: space or cmaes"));
        assertTrue(error("space", "stepSeconds:0.01", "--type", "0,2").contains("the search tunes one robot type, got [0, 2]"));
        assertTrue(error("space", "stepSeconds:0.01", "--type").contains("--type needs a value"));
        assertTrue(error("space", "stepSeconds:0.01", "--set", "stepSeconds=5").contains("stepSeconds must be in [0.04, 1.0], got 5.0"));
        assertTrue(error("space", "stepSeconds:0.01", "--jobs", "2").contains("space takes only"));
        assertTrue(cmaesError("cmaes").contains("cmaes needs FIELDS (field:step,...) first"));
        assertTrue(cmaesError("cmaes", "speed:1").contains("walk config has no field 'speed'"));
        assertTrue(cmaesError("cmaes", "stepSeconds:0.01", "--log").contains("--log needs a value"));
    }

    @Test
    void anUnknownFieldExitsWithStatus2AndItsName() throws Exception {
        Process p = new ProcessBuilder(java(), "-cp", System.getProperty("java.class.path"), WalkSearch.class.getName(), "space", "stepSeconds:0.01,speed:0.1")
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(2, p.waitFor());
        assertTrue(err.startsWith("walk-search: FIELDS: walk config has no field 'speed'"), err);
    }

    /** Worked by hand: 9 m in 15 s is 0.6 m/s, 10° of heading costs 0.02; a fall after 2.4 m: 2.4 / 15 - 0.2 - 5 · 0.002. */
    @Test
    void theTrialScoreIsTheTunersFormula() {
        assertEquals(0.58, new WalkTrial.Result(15.0, 9.0, 0.1, -10.0, false, Double.NaN).score(15), 1e-12);
        assertEquals(-0.05, new WalkTrial.Result(4.0, 2.4, 0.0, 5.0, true, 4.0).score(15), 1e-12);
    }

    /**
     * A fake `java` taking WalkTrial's place: it saves its arguments (per port) and scores the --set values,
     * best at stepSeconds 0.15, stepHeight 0.03, torsoLeanDeg 9; it fails (status 3) unless every one of the
     * 33 fields is set, and prints the ports as the detail.
     */
    private static Path fakeJava(Path dir) throws IOException {
        Path bin = Files.createDirectories(dir.resolve("bin")), f = bin.resolve("java");
        Files.writeString(f, String.join("\n",
                "#!/bin/sh",
                "for a in \"$@\"; do case \"$prev\" in --set) set=\"$a\";; --port) port=\"$a\";; --monitor-port) mon=\"$a\";; esac; prev=\"$a\"; done",
                "printf '%s\\n' \"$@\" > \"" + dir + "/args-$port\"",
                "echo \"$set\" | tr ',' '\\n' | awk -F= -v port=\"$port\" -v mon=\"$mon\" '",
                "{ v[$1] = $2 + 0; n++ }",
                "END { if (n != 33 || !(\"odometryTurn\" in v)) exit 3",
                "  s = -((v[\"stepSeconds\"] - 0.15) / 0.01) ^ 2 - ((v[\"stepHeight\"] - 0.03) / 0.004) ^ 2 - (v[\"torsoLeanDeg\"] - 9) ^ 2",
                "  printf \"SCORE %.17g port=%s mon=%s\\n\", s, port, mon }'", ""));
        assertTrue(f.toFile().setExecutable(true));
        return bin;
    }

    private record Run(int status, String out) {}

    private static Run walkSearch(Path bin, Map<String, String> env, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(java(), "-cp", System.getProperty("java.class.path"), WalkSearch.class.getName()));
        cmd.addAll(Arrays.asList(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        pb.environment().remove("WALK_CMAES_EVAL");
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        return new Run(p.waitFor(), out);
    }

    private static String java() { return Path.of(System.getProperty("java.home"), "bin", "java").toString(); }

    @Test
    void theSearchRunsTheTrialCommandOnTheSlotsPortsConvergesAndResumesFromItsLog(@TempDir Path dir) throws Exception {
        Path bin = fakeJava(dir), log = dir.resolve("walk.jsonl"), best = dir.resolve("best.json");
        String[] args = {"cmaes", "stepSeconds:0.01,stepHeight:0.004,torsoLeanDeg:1", "--port", "3910", "--monitor-port", "3920",
                "--search-seconds", "20", "--jobs", "2", "--log", log.toString(), "--generations", "30", "--seed", "3",
                "--best", best.toString(), "--work", dir.resolve("w").toString()};
        Run r = walkSearch(bin, Map.of(), args);
        assertEquals(0, r.status(), r.out());
        JsonNode b = new ObjectMapper().readTree(best.toFile());
        assertEquals(0.15, b.get("stepSeconds").doubleValue(), 0.001, r.out());
        assertEquals(0.03, b.get("stepHeight").doubleValue(), 0.0004, r.out());
        assertEquals(9.0, b.get("torsoLeanDeg").doubleValue(), 0.1, r.out());
        assertEquals(WalkConfig.DEFAULT.maxForward(), b.get("maxForward").doubleValue(), 0.0);   // not searched: the start's
        // each job slot on its own server: agent port 3910 + slot with monitor port 3920 + slot
        List<String> lines = Files.readAllLines(log);
        assertTrue(lines.stream().anyMatch(l -> l.contains("port=3910 mon=3920")), "slot 0 used");
        assertTrue(lines.stream().anyMatch(l -> l.contains("port=3911 mon=3921")), "slot 1 used");
        assertTrue(lines.stream().noneMatch(l -> l.contains("port=3910 mon=3921") || l.contains("port=3911 mon=3920")));
        // what the command gave the (fake) trial is a WalkTrial --score command line setting a valid config
        List<String> given = Files.readAllLines(dir.resolve("args-3911"));
        assertEquals(WalkTrial.class.getName(), given.get(2));
        WalkTrialOptions o = WalkTrialOptions.parse(given.subList(3, given.size()).toArray(String[]::new));
        assertTrue(o.score());
        assertEquals(List.of(0), o.types());
        assertEquals(20.0, o.searchSeconds());
        assertEquals(WalkConfig.FIELDS.size(), o.set().size());
        assertEquals(WalkConfig.DEFAULT.armSwingDeg(), o.config(0).armSwingDeg(), 0.0);

        Run again = walkSearch(bin, Map.of(), args);   // the same command: everything read from the log, nothing run
        assertEquals(0, again.status(), again.out());
        assertEquals(lines.size(), Files.readAllLines(log).size());
        assertTrue(again.out().contains("resuming from " + (lines.size() - 1) + " logged evaluations"), again.out());
        assertEquals(bestLine(r.out()), bestLine(again.out()));
    }

    private static String bestLine(String out) {
        return out.lines().filter(l -> l.startsWith("BEST ")).findFirst().orElseThrow(() -> new AssertionError("no BEST line:\n" + out));
    }

    @Test
    void walkCmaesEvalReplacesTheTrialCommand(@TempDir Path dir) throws Exception {
        Path log = dir.resolve("e.jsonl");
        Run r = walkSearch(fakeJava(dir), Map.of("WALK_CMAES_EVAL", "echo SCORE 1 replaced # {params}"), "cmaes", "stepSeconds:0.01",
                "--log", log.toString(), "--generations", "1", "--work", dir.resolve("w").toString());
        assertEquals(0, r.status(), r.out());
        List<String> evals = Files.readAllLines(log).subList(1, Files.readAllLines(log).size());
        assertFalse(evals.isEmpty());
        assertTrue(evals.stream().allMatch(l -> l.contains("\"replaced\"")), evals.toString());
        assertTrue(Files.exists(Path.of(log + ".space.json")));
    }
}

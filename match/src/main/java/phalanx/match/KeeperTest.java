package phalanx.match;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * scripts/phalanx keeper-test: the goalkeeper test of thesis 6.3. An attacking team plays against our goal
 * with no field players of ours, in three conditions: no goalkeeper, a goalkeeper that only stands
 * ({@code --behaviour still}), and our goalkeeper. Each condition is played {@code --games} times
 * (one half each by default) with the runner of scripts/phalanx match; the report is Table 6.3: goals
 * conceded per half beside the thesis's figures.
 */
public final class KeeperTest {
    static final String USAGE = """
            usage: scripts/phalanx keeper-test --attacker NAME='COMMAND' [--conditions none,still,keeper] [--games N]
                                               [--restarts N] [--out DIR] [match options]
                   scripts/phalanx keeper-test --report DIR
              COMMAND as for scripts/phalanx match ({host} {port} {dir}): a team that attacks (FC Portugal; the UT Austin
              Villa base code only plays its demo circle). Each condition is played N times (default 1),
              one half of 300 s unless --halves/--half-time say otherwise.
              --restarts N a game that stalled within its first game second (FC Portugal's sync start stalls the
                           server about 2 times in 9, docs/matches.md) is set aside as <condition>-NN.stallK and played again, up to
                           N times (default 2)
              --out DIR    results (<condition>-NN.json), match logs, table.md (default /tmp/phalanx-keeper/<time>)
            """ + MatchOptions.HELP;

    /** A condition of Table 6.3: its label in the results, the defending team's command, the thesis's goals a half. */
    record Condition(String name, String label, String command, double thesisGoalsPerHalf) {
        TeamCommand team() { return new TeamCommand(label, command); }
    }

    static final List<Condition> CONDITIONS = List.of(
            new Condition("none", "NoKeeper", "true {port}", 7),
            new Condition("still", "StillKeeper",
                    "env PHALANX_PLAYER_OPTS='--behaviour still' scripts/start.sh {host} {port} Phalanx --log-dir {dir} --only 1", 7),
            new Condition("keeper", "Keeper", "scripts/start.sh {host} {port} Phalanx --log-dir {dir} --only 1", 3));

    /** One row of the table: goals conceded in each counted half. */
    record Row(Condition condition, List<Integer> goalsPerGame, int halves, int notCompleted) {
        double mean() { return halves == 0 ? Double.NaN : goalsPerGame.stream().mapToInt(Integer::intValue).sum() / (double) halves; }
    }

    private KeeperTest() { }

    public static void main(String[] argv) {
        try {
            Set<String> own = Set.of("attacker", "conditions", "games", "restarts", "out", "report");
            Args a = MatchOptions.parse(argv, USAGE, "keeper-test", own, Set.of());
            if (a.get("report", null) != null) {
                System.out.print(report(Path.of(a.get("report", null))));
                System.exit(0);
            }
            String spec = a.get("attacker", null);
            if (spec == null) throw new IllegalArgumentException("keeper-test: --attacker NAME='COMMAND' is required");
            TeamCommand attacker = TeamCommand.parse(spec);
            List<Condition> conditions = conditions(a.get("conditions", "none,still,keeper"));
            int games = a.integer("games", 1, 1, 100);
            int restarts = a.integer("restarts", 2, 0, 10);
            Path out = Path.of(a.get("out", "/tmp/phalanx-keeper/" + MatchOptions.stamp()));
            Files.createDirectories(out);
            List<String> args = new ArrayList<>(List.of(argv));
            if (a.get("halves", null) == null) args.addAll(List.of("--halves", "1"));
            args.add("--allow-empty");
            Args match = MatchOptions.parse(args.toArray(String[]::new), USAGE, "keeper-test", own, Set.of());
            // Ctrl-C stops the game being played and everything it started (as scripts/phalanx tournament does).
            final MatchRunner[] current = new MatchRunner[1];
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                synchronized (current) {
                    if (current[0] != null) current[0].abort("keeper-test interrupted");
                }
            }, "keeper-test-stop"));
            for (Condition c : conditions) {
                for (int g = 1; g <= games; g++) {
                    String tag = String.format(Locale.ROOT, "%s-%02d", c.name(), g);
                    for (int attempt = 1; ; attempt++) {
                        MatchConfig cfg = MatchOptions.config(match, c.team(), attacker, out.resolve(tag), out.resolve(tag + ".json"));
                        MatchRunner runner = new MatchRunner(cfg, System.out);
                        synchronized (current) { current[0] = runner; }
                        MatchResult r = runner.run();
                        System.out.println(Tournament.progressLine(g, games, r));
                        if (!neverKickedOff(r) || attempt > restarts) break;
                        setAside(out, tag, attempt);
                        System.out.println("keeper-test: " + tag + " stalled in its first game second; set aside as " + tag + ".stall" + attempt
                                + ", playing it again (" + attempt + " of " + restarts + ")");
                    }
                }
            }
            System.out.print(report(out));
        } catch (IllegalArgumentException | IllegalStateException e) {
            System.err.println(e.getMessage());
            System.err.println("(scripts/phalanx keeper-test --help for the options)");
            System.exit(2);
        } catch (IOException e) {
            System.err.println("keeper-test: " + e.getMessage());
            System.exit(1);
        }
    }

    /**
     * A game that stalled before its first game second: the start failed and the keeper was never tested
     * (FC Portugal's stalls come at game time 0.0 or 0.04, right at the kick-off).
     */
    static boolean neverKickedOff(MatchResult r) {
        return !r.completed() && !(r.gameTime() >= 1.0);
    }

    /** Renames a failed start's result and logs out of the report's way ({@code <tag>.stallK[.json]}). */
    static void setAside(Path out, String tag, int attempt) throws IOException {
        for (String suffix : List.of(".json", "")) {
            Path p = out.resolve(tag + suffix);
            if (Files.exists(p)) Files.move(p, out.resolve(tag + ".stall" + attempt + suffix));
        }
    }

    static List<Condition> conditions(String list) {
        List<Condition> out = new ArrayList<>();
        for (String name : list.split(",")) {
            Condition c = CONDITIONS.stream().filter(x -> x.name().equals(name.trim())).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("keeper-test: unknown condition '" + name + "' (none, still, keeper)"));
            out.add(c);
        }
        return out;
    }

    /** Table 6.3 from the {@code <condition>-NN.json} results in {@code dir}; also written to table.md. */
    static String report(Path dir) throws IOException {
        Map<String, List<MatchResult>> byCondition = new LinkedHashMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.filter(p -> p.getFileName().toString().matches("[a-z]+-\\d+\\.json")).sorted().toList()) {
                byCondition.computeIfAbsent(p.getFileName().toString().replaceAll("-\\d+\\.json$", ""), k -> new ArrayList<>())
                        .add(MatchResult.read(p));
            }
        }
        if (byCondition.isEmpty()) throw new IOException("no <condition>-NN.json results in " + dir);
        StringBuilder md = new StringBuilder("Table 6.3 style: goals conceded per half, attacking team against our goal alone\n\n"
                + "| condition | halves | goals per game | goals per half | thesis | not completed |\n|---|---:|---|---:|---:|---:|\n");
        for (Condition c : CONDITIONS) {
            List<MatchResult> results = byCondition.get(c.name());
            if (results == null) continue;
            Row r = row(c, results);
            md.append(String.format(Locale.ROOT, "| %s | %d | %s | %s | %.0f | %d |%n", c.label(), r.halves(), r.goalsPerGame(),
                    r.halves() == 0 ? "-" : String.format(Locale.ROOT, "%.1f", r.mean()), c.thesisGoalsPerHalf(), r.notCompleted()));
        }
        Files.writeString(dir.resolve("table.md"), md.toString());
        return md + "\n(" + dir.resolve("table.md") + ")\n";
    }

    /** Only completed games count; the attacker is whichever team is not the condition's defender. */
    static Row row(Condition c, List<MatchResult> results) {
        List<Integer> goals = new ArrayList<>();
        int halves = 0, notCompleted = 0;
        for (MatchResult r : results) {
            if (!r.completed()) {
                notCompleted++;
                continue;
            }
            MatchResult.TeamResult attacker = r.left().label().equals(c.label()) ? r.right() : r.left();
            goals.add(attacker.score());
            halves += r.halves();
        }
        return new Row(c, goals, halves, notCompleted);
    }
}

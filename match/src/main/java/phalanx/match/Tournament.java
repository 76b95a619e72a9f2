package phalanx.match;

import java.io.IOException;
import java.io.PrintStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Stream;

/**
 * scripts/phalanx tournament: plays a list of opponents N games each against one team ({@code --us}), or a
 * round robin among all teams, one match after the other (each on a fresh server, so a server that
 * died is simply replaced), then prints Tables 6.4 and 6.5 and writes the goal-difference plot.
 * {@code --report DIR} only rebuilds the tables from the result files already in DIR.
 */
public final class Tournament {
    static final String USAGE = """
            usage: scripts/phalanx tournament --team NAME='COMMAND' --team NAME='COMMAND' ... [--us NAME] [--games N]
                                              [--round-robin] [--out DIR] [--jobs N] [--hosts FILE] [match options]
                   scripts/phalanx tournament --report DIR [--us NAME]
              COMMAND as for scripts/phalanx match ({host} {port} {dir}). Without --round-robin, --us (default: the
              first --team) plays every other team N times (default 1); the sides alternate.
              --out DIR    results (game-NN.json), match logs, tables.md, goal-difference.svg
                           (default /tmp/phalanx-tournaments/<time>)
              --quiet      only one progress line per game
            Games as GNU parallel jobs (match/README.md "Tournaments on GNU parallel"):
              --jobs N         N games at a time on this machine, each in its own port slot (without --hosts),
                               or N per host of --hosts (default 1)
              --hosts FILE     parallel's --sshloginfile: one host a line ([N/][user@]host, ':' for this machine);
                               every host needs the checkout (--remote-dir) and a server
              --retries N      tries per game, each on another host when there is one (default 3)
              --ssh CMD        the ssh command for --hosts (default ssh)
              --remote-dir D   the checkout on the hosts (default: this checkout's path; relative: from the home)
              --game-command C what a job runs from the checkout with the match options (default scripts/phalanx match)
              With --jobs or --hosts the same command with the same --out continues an interrupted tournament
              (DIR/joblog): logged games are not played again.
            """ + MatchOptions.HELP;

    /** One scheduled game: {@code first} starts first (left). */
    public record Fixture(TeamCommand first, TeamCommand second) { }

    private Tournament() { }

    /** The fixtures: us against each other team, or every pair; the sides alternate game by game. */
    public static List<Fixture> schedule(List<TeamCommand> teams, String us, int games, boolean roundRobin) {
        List<Fixture> out = new ArrayList<>();
        if (roundRobin) {
            for (int g = 0; g < games; g++) {
                for (int i = 0; i < teams.size(); i++) {
                    for (int j = i + 1; j < teams.size(); j++) {
                        out.add(g % 2 == 0 ? new Fixture(teams.get(i), teams.get(j)) : new Fixture(teams.get(j), teams.get(i)));
                    }
                }
            }
            return out;
        }
        TeamCommand home = teams.stream().filter(t -> t.label().equals(us)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("--us " + us + " is not one of the --team names"));
        for (TeamCommand t : teams) {
            if (t == home) continue;
            for (int g = 0; g < games; g++) out.add(g % 2 == 0 ? new Fixture(home, t) : new Fixture(t, home));
        }
        return out;
    }

    public static void main(String[] argv) {
        try {
            Args a = MatchOptions.parse(argv, USAGE, "tournament", ParallelTournament.OWN_VALUED, ParallelTournament.OWN_FLAGS);
            if (a.get("report", null) != null) {
                System.exit(report(Path.of(a.get("report", null)), a.get("us", null), System.out));
            }
            List<TeamCommand> teams = new ArrayList<>();
            for (String spec : a.all("team")) teams.add(TeamCommand.parse(spec));
            if (teams.size() < 2) throw new IllegalArgumentException("tournament: give at least two --team NAME=COMMAND");
            Set<String> names = new HashSet<>();
            for (TeamCommand t : teams) {
                if (!names.add(t.label())) throw new IllegalArgumentException("tournament: two teams are called " + t.label());
            }
            String us = a.get("us", teams.get(0).label());
            List<Fixture> fixtures = schedule(teams, us, a.integer("games", 1, 1, 1000), a.flag("round-robin"));
            Path out = Path.of(a.get("out", "/tmp/phalanx-tournaments/" + MatchOptions.stamp()));
            Files.createDirectories(out);
            boolean distributed = a.get("jobs", null) != null || a.get("hosts", null) != null;
            if (distributed) {
                Path root = ParallelHosts.checkout();   // each job runs its game from there
                ParallelTournament.Plan plan = new ParallelTournament.Plan(fixtures, out, root,
                        a.get("remote-dir", root.toString()), a.get("game-command", "scripts/phalanx match"),
                        ParallelTournament.matchArgs(argv), a.integer("jobs", 1, 1, MatchOptions.MAX_PORT_SLOT),
                        a.get("hosts", null) == null ? null : Path.of(a.get("hosts", null)), a.integer("retries", 3, 1, 100),
                        a.get("ssh", null), a.flag("quiet"));
                if (plan.hosts() != null) ParallelHosts.checkHostsFile(plan.hosts(), "tournament: ");
                MatchOptions.config(a, teams.get(0), teams.get(1), out, out.resolve("x.json")); // checks the options now
                int missing = ParallelTournament.run(plan, System.out);
                boolean any;
                try (Stream<Path> s = Files.list(out)) {
                    any = s.anyMatch(p -> p.getFileName().toString().matches("game-\\d+\\.json"));
                }
                int r = any ? report(out, a.flag("round-robin") ? null : us, System.out) : 0;
                System.exit(missing > 0 ? 1 : r);
            }
            MatchOptions.config(a, teams.get(0), teams.get(1), out, out.resolve("x.json")); // checks the options now
            play(fixtures, a, out, a.flag("quiet"));
            System.exit(report(out, a.flag("round-robin") ? null : us, System.out));
        } catch (IllegalArgumentException | IllegalStateException e) {
            System.err.println(e.getMessage());
            System.err.println("(scripts/phalanx tournament --help for the options)");
            System.exit(2);
        } catch (IOException e) {
            System.err.println("tournament: " + e.getMessage());
            System.exit(1);
        }
    }

    private static void play(List<Fixture> fixtures, Args a, Path out, boolean quiet) {
        final MatchRunner[] current = new MatchRunner[1];
        final boolean[] stopping = {false};
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            synchronized (current) {
                stopping[0] = true;
                if (current[0] != null) current[0].abort("tournament interrupted (Ctrl-C)");
            }
        }, "tournament-stop"));
        PrintStream silent = new PrintStream(OutputStream.nullOutputStream());
        for (int i = 0; i < fixtures.size(); i++) {
            Fixture f = fixtures.get(i);
            String tag = tag(i + 1);
            MatchRunner runner;
            synchronized (current) {
                if (stopping[0]) return;
                // A fresh server on fresh ports for every game: a crashed one is never reused.
                MatchConfig cfg = MatchOptions.config(a, f.first(), f.second(),
                        out.resolve(tag + "-" + f.first().label() + "-vs-" + f.second().label()), out.resolve(tag + ".json"));
                runner = new MatchRunner(cfg, quiet ? silent : System.out);
                current[0] = runner;
            }
            MatchResult r = runner.run();
            System.out.println(progressLine(i + 1, fixtures.size(), r));
            System.out.flush();
        }
    }

    /** The n-th game's name (1 ...): its result is {@code game-NN.json}. */
    static String tag(int n) { return String.format(Locale.ROOT, "game-%02d", n); }

    /** One line per game: score, whether it counts, and each team that was not complete. */
    static String progressLine(int n, int of, MatchResult r) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "[%d/%d] %s %d:%d %s", n, of, r.left().label(),
                r.left().score(), r.right().score(), r.right().label()));
        sb.append(String.format(Locale.ROOT, "  (%s, %.0f s wall, game time %.1f)", r.completed() ? "completed" : "NOT completed: " + r.reason(),
                r.wallSeconds(), r.gameTime()));
        for (MatchResult.TeamResult t : List.of(r.left(), r.right())) {
            if (t.status().equals("ok")) continue;
            sb.append("  ").append(t.label()).append(' ').append(t.status());
            if (!t.neverConnected().isEmpty() && !t.connected().isEmpty()) sb.append(" never connected ").append(t.neverConnected());
            if (!t.disconnected().isEmpty()) sb.append(" disconnected ").append(t.disconnected());
        }
        return sb.toString();
    }

    /** Reads every game-*.json in {@code dir}, prints the tables and writes tables.md and the plot. */
    static int report(Path dir, String us, PrintStream print) throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(p -> p.getFileName().toString().matches("game-\\d+\\.json")).sorted().toList();
        }
        if (files.isEmpty()) throw new IOException("no game-NN.json results in " + dir);
        List<Standings.Game> games = new ArrayList<>();
        for (Path p : files) games.add(Standings.Game.of(MatchResult.read(p)));
        StringBuilder md = new StringBuilder();
        md.append("Games (").append(files.size()).append(" in ").append(dir).append("):\n\n| # | left | score | right | counted | notes |\n|---:|---|:---:|---|---|---|\n");
        for (int i = 0; i < games.size(); i++) {
            Standings.Game g = games.get(i);
            md.append(String.format(Locale.ROOT, "| %d | %s | %d:%d | %s | %s | %s |%n", i + 1, g.left(), g.scoreLeft(), g.scoreRight(),
                    g.right(), g.counted() ? "yes" : "no", g.note().replace("|", "/")));
        }
        if (us != null) {
            List<Standings.OpponentRow> rows = Standings.versus(us, games);
            md.append("\nTable 6.4 style, ").append(us).append(" against each opponent:\n\n").append(Standings.table64(us, rows));
            Files.writeString(dir.resolve("goal-difference.svg"), GoalDifferencePlot.svg(us, rows));
        }
        md.append("\nTable 6.5 style, league (3 points a win, 1 a draw):\n\n").append(Standings.table65(Standings.league(games)));
        Files.writeString(dir.resolve("tables.md"), md.toString());
        print.print(md);
        print.println();
        print.println("tables in " + dir.resolve("tables.md") + (us != null ? ", plot in " + dir.resolve("goal-difference.svg") : ""));
        return 0;
    }
}

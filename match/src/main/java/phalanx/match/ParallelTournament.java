package phalanx.match;

import phalanx.match.Tournament.Fixture;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import static phalanx.match.ParallelHosts.quote;

/**
 * The {@code --jobs N} / {@code --hosts FILE} path of scripts/phalanx tournament: every game is one GNU
 * parallel job. The games go to DIR/jobs.tsv (tag, game folder, the two team specs, one game a line) and
 * parallel runs scripts/lib/tools/tournament-job for each, N at a time on this machine ({@code -S :}) or
 * on the hosts of an {@code --sshloginfile} (N per host), each job in its own port slot ({@code {%}},
 * {@code --port-slot}). {@code --joblog DIR/joblog} with {@code --resume-failed}: the same command again
 * continues an interrupted tournament and retries games that failed on every host they were tried on,
 * never playing a logged game again; {@code --retries} moves a game whose host failed to another host;
 * {@code --return} brings a remote game's result JSON, its output and its monitor log back into DIR.
 * The tables are then built from DIR's game-NN.json exactly as after the serial path.
 */
final class ParallelTournament {
    /** The tournament options that are not passed on to each game. */
    static final Set<String> OWN_VALUED = Set.of("team", "us", "games", "out", "report", "jobs", "hosts", "retries", "ssh",
            "game-command", "remote-dir");
    static final Set<String> OWN_FLAGS = Set.of("round-robin", "quiet");
    /** Ports are the job slot's ({@code --port-slot}); a fixed port would collide between jobs. */
    static final Set<String> REFUSED = Set.of("agent-port", "monitor-port", "port-slot");
    /** parallel's stop sequence for a job: SIGTERM, then up to 30 s for the match to stop its server and teams. */
    static final String TERMSEQ = "TERM,30000,KILL,25";

    /**
     * One parallel run. {@code root} is this checkout, {@code remoteRoot} the checkout's path on the hosts
     * (relative: to the remote home), {@code gameCommand} shell text run from the checkout with the match
     * arguments (default {@code scripts/phalanx match}), {@code matchArgs} the match options for every game.
     */
    record Plan(List<Fixture> fixtures, Path out, Path root, String remoteRoot, String gameCommand, List<String> matchArgs,
                int jobs, Path hosts, int retries, String ssh, boolean quiet) { }

    private ParallelTournament() { }

    /** The match options of a tournament command line, in order, without the tournament's own. */
    static List<String> matchArgs(String[] argv) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < argv.length; i++) {
            String name = argv[i].startsWith("--") ? argv[i].substring(2) : argv[i];
            if (REFUSED.contains(name)) {
                throw new IllegalArgumentException("tournament: --" + name + " cannot be given with --jobs or --hosts: every job "
                        + "chooses free ports in its own slot (--port-slot)");
            }
            boolean valued = MatchOptions.VALUED.contains(name) || OWN_VALUED.contains(name);
            boolean pass = MatchOptions.VALUED.contains(name) || MatchOptions.FLAGS.contains(name);
            if (pass) {
                out.add(argv[i]);
                if (valued) out.add(argv[i + 1]);
            }
            if (valued) i++;
        }
        return out;
    }

    /** DIR/jobs.tsv: one line per game, tag, game folder, first (left) and second team as NAME=COMMAND. */
    static String jobsTable(List<Fixture> fixtures) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < fixtures.size(); i++) {
            Fixture f = fixtures.get(i);
            String tag = Tournament.tag(i + 1);
            sb.append(tag).append('\t').append(tag).append('-').append(f.first().label()).append("-vs-").append(f.second().label())
                    .append('\t').append(spec(f.first())).append('\t').append(spec(f.second())).append('\n');
        }
        return sb.toString();
    }

    private static String spec(TeamCommand t) {
        if (t.template().matches("(?s).*[\t\n\r].*")) {
            throw new IllegalArgumentException("team " + t.label() + ": a start command with a tab or a line break cannot be a parallel job");
        }
        return t.label() + "=" + t.template();
    }

    /**
     * The command parallel runs per game ({1} tag, {2} game folder, {3} {4} teams, {%} job slot). It starts
     * with {@code exec}: on a remote host parallel's wrapper sends SIGTERM to the job and, as soon as the
     * shell it started exits, SIGKILL (parallel 20221122: the child's exit cuts --termseq's wait short). A
     * shell between the wrapper and tournament-job would die at once on SIGTERM, and the match would be
     * killed before it stopped its server and teams. With exec, that shell is tournament-job, which waits.
     */
    static String template(Plan p) {
        StringBuilder sb = new StringBuilder("exec bash ").append(ParallelHosts.tool(p.remoteRoot(), "tournament-job")).append(" {1} {2} {%} ")
                .append(quote(p.out().toAbsolutePath().toString())).append(p.quiet() ? " 1" : " 0").append(" -- ")
                .append(p.gameCommand()).append(" --left {3} --right {4}");
        for (String a : p.matchArgs()) sb.append(' ').append(quote(a));
        return sb.toString();
    }

    /** The parallel command line (with --hosts it writes DIR/sshloginfile). */
    static List<String> command(Plan p) throws IOException {
        Path out = p.out().toAbsolutePath();
        List<String> c = new ArrayList<>(List.of("parallel", "--colsep", "\\t", "--joblog", out.resolve("joblog").toString(),
                "--resume-failed", "--retries", Integer.toString(p.retries()), "--termseq", TERMSEQ));
        if (p.hosts() != null) {
            // On a host the job runs in ~/phalanx-tournaments/<this folder's name>; what --return names
            // comes back here, the rest (server and team logs) stays there.
            c.addAll(ParallelHosts.sshOptions(p.hosts(), p.jobs(), p.root(), "phalanx-tournaments/" + out.getFileName(), out));
            c.addAll(List.of("--return", "{1}.json", "--return", "{1}.out", "--return", "{2}/monitor.log.gz", "--cleanup"));
        } else {
            c.addAll(List.of("-S", ":", "--jobs", Integer.toString(p.jobs())));
        }
        if (!p.quiet()) c.addAll(List.of("--line-buffer", "--tagstring", "{1}"));
        c.addAll(List.of("-a", out.resolve("jobs.tsv").toString(), template(p)));
        return c;
    }

    /**
     * Writes (or, resuming, checks) DIR/jobs.tsv and DIR/job-command.txt, runs parallel to its end and
     * returns its exit status: 0 when every game was played, else the number of games still unplayed.
     */
    static int run(Plan p, PrintStream print) throws IOException {
        if (!ParallelHosts.available()) {
            throw new IllegalStateException("tournament: --jobs and --hosts need GNU parallel (Debian package parallel; scripts/setup.sh installs it)");
        }
        Path out = p.out().toAbsolutePath();
        Files.createDirectories(out);
        String jobs = jobsTable(p.fixtures());
        String command = template(p) + "\n";
        keepOrCheck(out.resolve("jobs.tsv"), jobs);
        keepOrCheck(out.resolve("job-command.txt"), command);
        Path joblog = out.resolve("joblog");
        JoblogWatch watch = new JoblogWatch(joblog, out, p.fixtures().size(), print);
        int before = watch.scan(false);
        if (before > 0 || Files.exists(joblog)) {
            print.printf(Locale.ROOT, "tournament: resuming %s: %d of %d games already played (joblog)%n", out, before, p.fixtures().size());
        }
        ProcessBuilder pb = new ProcessBuilder(command(p)).directory(out.toFile()).inheritIO();
        pb.redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")));
        ParallelHosts.environment(pb.environment(), out.resolve("failures.log"), p.ssh(), "game-%02d");
        Process proc = pb.start();
        Thread hook = new Thread(() -> {
            if (proc.isAlive()) {
                proc.destroy(); // SIGTERM: parallel stops its jobs (--termseq) and logs none of them
                try {
                    proc.waitFor(90, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }, "tournament-parallel-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        int status;
        try {
            while (!proc.waitFor(500, TimeUnit.MILLISECONDS)) watch.scan(true);
            status = proc.exitValue();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            proc.destroy();
            throw new IOException("interrupted while parallel ran");
        } finally {
            try { Runtime.getRuntime().removeShutdownHook(hook); } catch (IllegalStateException ignored) { }
        }
        int played = watch.scan(true);
        Path failures = out.resolve("failures.log");
        if (Files.exists(failures)) {
            List<String> lines = Files.readAllLines(failures);
            print.printf(Locale.ROOT, "tournament: %d failed attempt(s) of a game on a host (a host that could not play, or a "
                    + "stopped job), in %s:%n", lines.size(), failures);
            for (String l : lines) print.println("  " + l);
        }
        int missing = p.fixtures().size() - played;
        if (missing > 0) {
            print.printf(Locale.ROOT, "tournament: %d of %d games not played (parallel exit %d); the same command again plays them%n",
                    missing, p.fixtures().size(), status);
        }
        return missing;
    }

    /** Writes the file, or when it exists checks it holds the same: a resumed run must be the same tournament. */
    private static void keepOrCheck(Path file, String text) throws IOException {
        if (!Files.exists(file)) {
            Files.writeString(file, text, StandardCharsets.UTF_8);
            return;
        }
        if (!Files.readString(file, StandardCharsets.UTF_8).equals(text)) {
            throw new IllegalArgumentException("tournament: " + file + " is from another tournament (other teams, games or match "
                    + "options); resume with the same command or give a new --out");
        }
    }

    /** Follows the joblog and prints a progress line for every game that finished since the last look. */
    static final class JoblogWatch {
        private final Path joblog, out;
        private final int total;
        private final PrintStream print;
        private final Set<Integer> played = new HashSet<>();
        private int linesSeen;

        JoblogWatch(Path joblog, Path out, int total, PrintStream print) {
            this.joblog = joblog;
            this.out = out;
            this.total = total;
            this.print = print;
        }

        /** Reads new joblog lines; returns how many games are played (exit 0). */
        int scan(boolean report) {
            List<String> lines;
            try {
                if (!Files.exists(joblog)) return played.size();
                lines = Files.readAllLines(joblog);
            } catch (IOException e) {
                return played.size();
            }
            for (int i = linesSeen; i < lines.size(); i++) {
                String line = lines.get(i);
                if (line.startsWith("Seq\t") || line.isBlank()) continue;
                if (i == lines.size() - 1 && !complete(line)) break; // still being written
                String[] f = line.split("\t", 9);
                linesSeen = i + 1;
                int seq = Integer.parseInt(f[0]);
                int exit = Integer.parseInt(f[6].strip());
                String host = f[1];
                if (exit == 0) played.add(seq);
                if (!report) continue;
                String tag = Tournament.tag(seq);
                if (exit == 0) {
                    try {
                        MatchResult r = MatchResult.read(out.resolve(tag + ".json"));
                        print.println(Tournament.progressLine(played.size(), total, r) + "  on " + host + " (" + tag + ")");
                    } catch (IOException e) {
                        print.println("tournament: " + tag + " on " + host + ": " + e.getMessage());
                    }
                } else {
                    print.printf(Locale.ROOT, "tournament: %s failed on %s (exit %d, signal %s) on every host it was tried on%n", tag,
                            host, exit, f[7].strip());
                }
            }
            print.flush();
            return played.size();
        }

        private static boolean complete(String line) { return line.split("\t", -1).length >= 9; }
    }
}

package phalanx.bench.search;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import phalanx.match.ParallelHosts;

/**
 * Evaluates candidates by running a shell command per candidate, up to {@code jobs} at a time (issue 21).
 * The command is run with {@code sh -c}; {@code {params}} in it is replaced by the path of a JSON file with
 * the candidate's parameters (all keys), and the environment has {@code SEARCH_SLOT} = 0 .. jobs-1, the job
 * slot, so that parallel evaluations can use servers of their own (kick-search's {@code score} mode adds the
 * slot to KICK_PORT and KICK_MONITOR_PORT). The command's score is the last stdout line
 * {@code SCORE <number> [detail]} (higher is better). A command that exits non-zero, prints no SCORE line or
 * runs over the timeout ends the search with its output's tail; the evaluations finished before it are in
 * the log, so the search resumes from there.
 *
 * <p>With {@code viaParallel} the batch is handed to GNU parallel instead of threads ({@code parallel -j N
 * --joblog ... --timeout S}, as the tournament uses it; {@code {%}} - 1 is the slot): one job per candidate,
 * scripts/lib/tools/search-job, each job's output in a file beside its candidate, read as soon as the joblog
 * lists the job. With {@link Hosts} the jobs go to the hosts of an {@code --sshloginfile} through the
 * tournament's ssh wrapper ({@link ParallelHosts}): the candidate's file is transferred, its output comes
 * back (--return), a job that fails on a host is tried on another (--retries; each failed try is a line in
 * WORK/failures.log with the host's name), and each host numbers its own slots 0..N-1 (search-job).
 */
public final class CommandEvaluator implements CmaesSearch.Evaluator {

    private static final Pattern SCORE = Pattern.compile("^SCORE\\s+(\\S+)\\s*(.*)$");
    private static final ObjectMapper JSON = new ObjectMapper();

    private final String command;
    private final int jobs;
    private final long timeoutSeconds;
    private final Path workDir;
    private final boolean viaParallel;
    private final Hosts hosts;
    private int batches;

    /**
     * Other machines for the GNU parallel path: parallel's --sshloginfile {@code file}, the ssh command
     * ({@code ssh}, null = ssh), the checkout on the hosts ({@code remoteDir}, null = this checkout's path;
     * relative: from the home) and the tries per candidate.
     */
    public record Hosts(Path file, String ssh, String remoteDir, int retries) {
        public Hosts {
            if (retries < 1) throw new IllegalArgumentException("--retries must be at least 1, got " + retries);
            ParallelHosts.checkHostsFile(file, "");
        }
    }

    public CommandEvaluator(String command, int jobs, long timeoutSeconds, Path workDir) {
        this(command, jobs, timeoutSeconds, workDir, false);
    }

    public CommandEvaluator(String command, int jobs, long timeoutSeconds, Path workDir, boolean viaParallel) {
        this(command, jobs, timeoutSeconds, workDir, viaParallel, null);
    }

    /** {@code hosts} non-null: through GNU parallel on those hosts ({@code viaParallel} is then implied). */
    public CommandEvaluator(String command, int jobs, long timeoutSeconds, Path workDir, boolean viaParallel, Hosts hosts) {
        if (command == null || command.isBlank()) throw new IllegalArgumentException("--eval needs a command");
        if (!command.contains("{params}")) throw new IllegalArgumentException("--eval command must contain {params} (the candidate's JSON file): " + command);
        if (jobs < 1) throw new IllegalArgumentException("--jobs must be at least 1, got " + jobs);
        if (timeoutSeconds < 1) throw new IllegalArgumentException("--timeout must be at least 1 s, got " + timeoutSeconds);
        this.command = command;
        this.jobs = jobs;
        this.timeoutSeconds = timeoutSeconds;
        this.workDir = workDir;
        this.viaParallel = viaParallel || hosts != null;
        this.hosts = hosts;
    }

    /** The score line of a command's output: {score, detail}, or null when there is none. */
    static String[] parseScore(String stdout) {
        String[] found = null;
        for (String line : stdout.split("\n")) {
            Matcher m = SCORE.matcher(line.strip());
            if (m.matches()) found = new String[] {m.group(1), m.group(2)};
        }
        return found;
    }

    @Override
    public void evaluate(List<Map<String, Double>> batch, CmaesSearch.ResultSink done) throws IOException, InterruptedException {
        Files.createDirectories(workDir);
        if (viaParallel) { evaluateWithParallel(batch, done); return; }
        BlockingQueue<Integer> slots = new ArrayBlockingQueue<>(jobs);
        for (int s = 0; s < jobs; s++) slots.add(s);
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(jobs, batch.size()));
        List<Future<?>> futures = new ArrayList<>();
        try {
            for (int i = 0; i < batch.size(); i++) {
                final int index = i;
                futures.add(pool.submit(() -> {
                    int slot = slots.take();
                    try {
                        runOne(index, slot, batch.get(index), done);
                    } finally {
                        slots.add(slot);
                    }
                    return null;
                }));
            }
            for (Future<?> f : futures) {
                try {
                    f.get();
                } catch (java.util.concurrent.ExecutionException e) {
                    Throwable c = e.getCause();
                    if (c instanceof IOException io) throw io;
                    throw new IOException(c.getMessage(), c);
                }
            }
        } finally {
            // after a failure: the candidates not started are dropped, the running ones stopped (their
            // processes destroyed) before the search reports the failure
            pool.shutdownNow();
            pool.awaitTermination(60, TimeUnit.SECONDS);
        }
    }

    private void runOne(int index, int slot, Map<String, Double> params, CmaesSearch.ResultSink done) throws IOException, InterruptedException {
        Path file = workDir.resolve("candidate-slot" + slot + ".json");
        Files.writeString(file, JSON.writeValueAsString(params), StandardCharsets.UTF_8);
        String cmd = command.replace("{params}", "'" + file.toAbsolutePath().toString().replace("'", "'\\''") + "'");
        ProcessBuilder pb = new ProcessBuilder("sh", "-c", cmd);
        pb.environment().put("SEARCH_SLOT", Integer.toString(slot));
        Path out = workDir.resolve("candidate-slot" + slot + ".out"), err = workDir.resolve("candidate-slot" + slot + ".err");
        pb.redirectOutput(out.toFile()).redirectError(err.toFile());
        Process p = pb.start();
        try {
            if (!p.waitFor(timeoutSeconds, TimeUnit.SECONDS)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                throw new IOException("evaluation timed out after " + timeoutSeconds + " s: " + cmd);
            }
        } finally {
            if (p.isAlive()) { p.descendants().forEach(ProcessHandle::destroyForcibly); p.destroyForcibly(); }
        }
        String stdout = Files.readString(out, StandardCharsets.UTF_8);
        String[] s = parseScore(stdout);
        if (p.exitValue() != 0 || s == null) {
            String tail = tail(Files.readString(err, StandardCharsets.UTF_8) + stdout);
            throw new IOException("evaluation " + (p.exitValue() != 0 ? "exited with status " + p.exitValue() : "printed no 'SCORE <number>' line")
                    + ": " + cmd + "\n" + tail);
        }
        double score;
        try {
            score = Double.parseDouble(s[0]);
        } catch (NumberFormatException e) {
            throw new IOException("evaluation printed a SCORE that is not a number (" + s[0] + "): " + cmd);
        }
        if (!Double.isFinite(score)) throw new IOException("evaluation printed a SCORE that is not finite (" + s[0] + "): " + cmd);
        done.accept(index, score, s[1]);
    }

    private void evaluateWithParallel(List<Map<String, Double>> batch, CmaesSearch.ResultSink done) throws IOException, InterruptedException {
        // batch-K counts from 1 again in a resumed run (the logged generations are not evaluated): what a
        // killed run left there is removed, so that no old output is read as this batch's
        Path dir = workDir.resolve("batch-" + (++batches)).toAbsolutePath();
        if (Files.isDirectory(dir)) {
            try (var old = Files.walk(dir)) {
                for (Path f : (Iterable<Path>) old.sorted(java.util.Comparator.reverseOrder())::iterator) if (!f.equals(dir)) Files.delete(f);
            }
        }
        Files.createDirectories(dir);
        List<String> files = new ArrayList<>();
        for (int i = 0; i < batch.size(); i++) {
            Files.writeString(dir.resolve("cand-" + (i + 1) + ".json"), JSON.writeValueAsString(batch.get(i)), StandardCharsets.UTF_8);
            files.add(dir + "/./cand-" + (i + 1) + ".json");   // "/./": on a host, the file goes to the job's folder
        }
        Path joblog = dir.resolve("joblog"), failures = workDir.toAbsolutePath().resolve("failures.log");
        Path root = ParallelHosts.checkout();
        List<String> cmd = new ArrayList<>(List.of("parallel", "--joblog", joblog.toString(),
                "--timeout", Long.toString(timeoutSeconds), "--halt", "never"));
        String job;
        if (hosts == null) {
            cmd.addAll(List.of("-j", Integer.toString(jobs)));
            job = "bash " + ParallelHosts.quote(root.resolve("scripts/lib/tools/search-job").toString()) + " {} {%}";
        } else {
            // one folder per job, right in the host's home: --cleanup runs rmdir on every empty folder of the
            // path (GNU parallel 20221122), so a parent shared by a host's jobs vanished under the next job's
            // `mkdir -p` and its params file was not transferred (CI, 2026-12-07; motion/README.md)
            cmd.addAll(ParallelHosts.sshOptions(hosts.file(), jobs, root,
                    "phalanx-search-" + workDir.toAbsolutePath().getFileName() + "-" + dir.getFileName() + "-{#}", dir));
            cmd.addAll(List.of("--env", "SEARCH_EVAL", "--transferfile", "{}", "--return", "{.}.out", "--return", "{.}.err", "--cleanup",
                    "--retries", Integer.toString(hosts.retries())));
            // exec: parallel's remote wrapper stops the job it started (ParallelTournament.template)
            job = "exec bash " + ParallelHosts.tool(hosts.remoteDir() != null ? hosts.remoteDir() : root.toString(), "search-job") + " {} host";
        }
        cmd.add(job);
        cmd.add(":::");
        cmd.addAll(files);
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("parallel.out").toFile());
        // a ':' line of the hosts file runs its jobs here, in --workdir under parallel's folder: this batch's
        if (hosts != null) pb.directory(dir.toFile());
        pb.environment().put("SEARCH_EVAL", command);
        if (hosts != null) ParallelHosts.environment(pb.environment(), failures, hosts.ssh(), "batch-" + batches + "/cand-%d");
        long failuresBefore = Files.exists(failures) ? Files.readAllLines(failures).size() : 0;
        Process p;
        try {
            p = pb.start();
        } catch (IOException e) {
            throw new IOException("cannot run GNU parallel (Debian package 'parallel'): " + e.getMessage(), e);
        }
        // a search stopped by SIGTERM (or Ctrl-C) stops parallel, which stops its jobs; the evaluations
        // already read are in the search's log
        Thread hook = new Thread(() -> {
            p.destroy();
            try { p.waitFor(60, TimeUnit.SECONDS); } catch (InterruptedException e) { Thread.currentThread().interrupt(); }
        }, "cmaes-parallel-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        boolean[] read = new boolean[files.size()];
        try {
            // each result goes to the search (and its log) as soon as the joblog lists it, as on the thread path
            while (!p.waitFor(200, TimeUnit.MILLISECONDS)) readFinished(dir, joblog, read, done);
        } finally {
            try { Runtime.getRuntime().removeShutdownHook(hook); } catch (IllegalStateException ignored) { }
            if (p.isAlive()) p.destroy();
        }
        Map<Integer, String[]> finished = readFinished(dir, joblog, read, done);
        if (Files.exists(failures)) {
            List<String> lines = Files.readAllLines(failures);
            for (String l : lines.subList((int) Math.min(failuresBefore, lines.size()), lines.size()))
                System.err.println("cmaes: a failed try on a host (parallel tried it again elsewhere): " + l);
        }
        for (int i = 0; i < files.size(); i++) {
            if (read[i]) continue;
            String b = dir.resolve("cand-" + (i + 1)).toString();
            String output = tail(text(Path.of(b + ".err")) + text(Path.of(b + ".out")) + (hosts != null ? text(dir.resolve("parallel.out")) : ""));
            String[] line = finished.get(i + 1);
            String where = files.get(i) + (hosts != null ? " (tries that failed on a host: " + failures + ")" : "");
            if (line == null)
                throw new IOException("GNU parallel job " + (i + 1) + " of batch " + batches + " did not finish (parallel failed: "
                        + dir.resolve("parallel.out") + ")\n" + output);
            int status = Integer.parseInt(line[6].strip()), signal = Integer.parseInt(line[7].strip());
            if (signal != 0)
                throw new IOException("evaluation stopped by signal " + signal + " (a --timeout of " + timeoutSeconds + " s?): " + where + "\n" + output);
            if (status != 0) throw new IOException("evaluation exited with status " + status + ": " + command + " on " + where + "\n" + output);
            String[] sc = parseScore(text(Path.of(b + ".out")));
            if (sc == null) throw new IOException("evaluation printed no 'SCORE <number>' line: " + command + " on " + where + "\n" + output);
            throw new IOException("evaluation printed a SCORE that is not a finite number (" + sc[0] + "): " + where);
        }
    }

    /**
     * Passes every candidate the joblog lists as done (exit 0) whose output has its score to {@code done};
     * returns every joblog line by sequence number (1-based). A line without its output yet (--return
     * still copying) is read on a later call.
     */
    private static Map<Integer, String[]> readFinished(Path dir, Path joblog, boolean[] read, CmaesSearch.ResultSink done) throws IOException {
        Map<Integer, String[]> lines = new java.util.HashMap<>();
        if (!Files.exists(joblog)) return lines;
        for (String l : Files.readAllLines(joblog)) {
            String[] f = l.split("\t", 9);
            if (f.length < 9 || !f[0].matches("\\d+")) continue;   // the header, or a line still being written
            int seq = Integer.parseInt(f[0]);
            lines.put(seq, f);
            if (read[seq - 1] || !f[6].strip().equals("0") || !f[7].strip().equals("0")) continue;
            String[] s = parseScore(text(dir.resolve("cand-" + seq + ".out")));
            if (s == null) continue;
            double score;
            try {
                score = Double.parseDouble(s[0]);
            } catch (NumberFormatException e) {
                continue;   // reported as such after the batch
            }
            if (!Double.isFinite(score)) continue;
            read[seq - 1] = true;
            done.accept(seq - 1, score, s[1]);
        }
        return lines;
    }

    private static String text(Path f) throws IOException {
        return Files.exists(f) ? Files.readString(f, StandardCharsets.UTF_8) : "";
    }

    private static String tail(String s) {
        return s.length() <= 2000 ? s : s.substring(s.length() - 2000);
    }
}

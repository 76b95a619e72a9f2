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
 * --joblog ... --timeout S}, as the tournament uses it; {@code {%}} - 1 is the slot): one job per candidate
 * running a small job script, each job's output in a file beside its candidate. The results are read when
 * the whole batch is done, so a kill in the middle of a batch loses that batch's finished evaluations (the
 * thread path logs each as it finishes). Local only here: no --sshloginfile yet.
 */
public final class CommandEvaluator implements CmaesSearch.Evaluator {

    private static final Pattern SCORE = Pattern.compile("^SCORE\\s+(\\S+)\\s*(.*)$");
    private static final ObjectMapper JSON = new ObjectMapper();

    private final String command;
    private final int jobs;
    private final long timeoutSeconds;
    private final Path workDir;
    private final boolean viaParallel;
    private int batches;

    public CommandEvaluator(String command, int jobs, long timeoutSeconds, Path workDir) {
        this(command, jobs, timeoutSeconds, workDir, false);
    }

    public CommandEvaluator(String command, int jobs, long timeoutSeconds, Path workDir, boolean viaParallel) {
        if (command == null || command.isBlank()) throw new IllegalArgumentException("--eval needs a command");
        if (!command.contains("{params}")) throw new IllegalArgumentException("--eval command must contain {params} (the candidate's JSON file): " + command);
        if (jobs < 1) throw new IllegalArgumentException("--jobs must be at least 1, got " + jobs);
        if (timeoutSeconds < 1) throw new IllegalArgumentException("--timeout must be at least 1 s, got " + timeoutSeconds);
        this.command = command;
        this.jobs = jobs;
        this.timeoutSeconds = timeoutSeconds;
        this.workDir = workDir;
        this.viaParallel = viaParallel;
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
        Path dir = workDir.resolve("batch-" + (++batches));
        Files.createDirectories(dir);
        List<String> files = new ArrayList<>();
        for (int i = 0; i < batch.size(); i++) {
            Path f = dir.resolve("cand-" + i + ".json");
            Files.writeString(f, JSON.writeValueAsString(batch.get(i)), StandardCharsets.UTF_8);
            files.add(f.toAbsolutePath().toString());
        }
        Path job = dir.resolve("job.sh");
        // $1 = the candidate's file, $2 = parallel's job slot (1-based)
        Files.writeString(job, String.join("\n",
                "SEARCH_SLOT=$(($2 - 1)); export SEARCH_SLOT",
                "c=\"$1\"; b=\"${c%.json}\"",
                "(", command.replace("{params}", "\"$c\""), ") > \"$b.out\" 2> \"$b.err\"",   // own lines: a '#' in it ends at the newline
                "echo $? > \"$b.rc\"", ""), StandardCharsets.UTF_8);
        List<String> cmd = new ArrayList<>(List.of("parallel", "-j", Integer.toString(jobs), "--joblog", dir.resolve("joblog").toString(),
                "--timeout", Long.toString(timeoutSeconds), "--halt", "never", "sh", job.toString(), "{}", "{%}", ":::"));
        cmd.addAll(files);
        Process p;
        try {
            p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("parallel.out").toFile()).start();
        } catch (IOException e) {
            throw new IOException("cannot run GNU parallel (Debian package 'parallel'): " + e.getMessage(), e);
        }
        p.waitFor();
        for (int i = 0; i < files.size(); i++) {
            String b = files.get(i).substring(0, files.get(i).length() - ".json".length());
            Path rc = Path.of(b + ".rc");
            String out = Files.exists(Path.of(b + ".out")) ? Files.readString(Path.of(b + ".out")) : "";
            String err = Files.exists(Path.of(b + ".err")) ? Files.readString(Path.of(b + ".err")) : "";
            if (!Files.exists(rc))
                throw new IOException("GNU parallel job " + (i + 1) + " of batch " + batches + " did not finish (timed out after "
                        + timeoutSeconds + " s, or parallel failed: " + dir.resolve("parallel.out") + ")\n" + tail(err + out));
            String[] s = parseScore(out);
            int status = Integer.parseInt(Files.readString(rc).strip());
            if (status != 0 || s == null)
                throw new IOException("evaluation " + (status != 0 ? "exited with status " + status : "printed no 'SCORE <number>' line")
                        + ": " + command + " on " + files.get(i) + "\n" + tail(err + out));
            double score;
            try {
                score = Double.parseDouble(s[0]);
            } catch (NumberFormatException e) {
                throw new IOException("evaluation printed a SCORE that is not a number (" + s[0] + "): " + files.get(i));
            }
            done.accept(i, score, s[1]);
        }
    }

    private static String tail(String s) {
        return s.length() <= 2000 ? s : s.substring(s.length() - 2000);
    }
}

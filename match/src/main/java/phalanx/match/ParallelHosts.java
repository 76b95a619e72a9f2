package phalanx.match;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * What the runs that hand their jobs to GNU parallel on other hosts share (issue 21): the tournament
 * ({@link ParallelTournament}) and the CMA-ES kick search ({@code phalanx.bench.search.CommandEvaluator}).
 * A job logs in through scripts/lib/tools/tournament-ssh (the real ssh, and a line in a failures file for
 * every try that fails on a host), runs a script of the host's own checkout (same path as here, or
 * {@code --remote-dir}) in a work folder under the host's home, and parallel brings its files back.
 */
public final class ParallelHosts {
    private ParallelHosts() { }

    /** This checkout: scripts/lib/run-java sets phalanx.root; a test runs from the repository root. */
    public static Path checkout() {
        return Path.of(System.getProperty("phalanx.root", System.getProperty("user.dir"))).toAbsolutePath();
    }

    /** Single quotes for the shell. */
    public static String quote(String s) { return "'" + s.replace("'", "'\\''") + "'"; }

    /** Shell text naming scripts/lib/tools/TOOL in the checkout {@code remoteRoot} on a host (relative: from its home). */
    public static String tool(String remoteRoot, String tool) {
        String root = remoteRoot.startsWith("/") ? quote(remoteRoot) : "~/" + quote(remoteRoot);
        return root + "/scripts/lib/tools/" + tool;
    }

    /**
     * Refuses a hosts file that is missing or names no host (parallel would run nothing, or everything
     * here). {@code prefix} starts the message ("tournament: ", or "" when the caller adds its own).
     */
    public static void checkHostsFile(Path hosts, String prefix) {
        if (!Files.isRegularFile(hosts)) throw new IllegalArgumentException(prefix + "--hosts " + hosts + " is not a file");
        List<String> lines;
        try {
            lines = Files.readAllLines(hosts, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalArgumentException(prefix + "--hosts " + hosts + " cannot be read: " + e.getMessage());
        }
        if (lines.stream().map(String::strip).noneMatch(l -> !l.isEmpty() && !l.startsWith("#"))) {
            throw new IllegalArgumentException(prefix + "--hosts " + hosts + " names no host (one [N/][user@]host a line, ':' for this machine)");
        }
    }

    /**
     * parallel's options for the hosts of {@code hosts}, {@code jobs} at a time on each host that has no
     * {@code N/} of its own: log in through tournament-ssh of {@code root}, run each job in {@code workdir}
     * (relative to the host's home). The caller adds --transferfile/--return/--cleanup, and no --jobs of
     * its own. parallel reads N/ as the host's number of cores and runs --jobs per host whatever N says
     * (20221122: with --jobs 1, 2/h1 runs one job), so the hosts go to {@code dir}/sshloginfile with
     * {@code jobs/} in front of every line without N/, and parallel runs --jobs 100% (N per host).
     */
    public static List<String> sshOptions(Path hosts, int jobs, Path root, String workdir, Path dir) throws IOException {
        StringBuilder sb = new StringBuilder();
        for (String line : Files.readAllLines(hosts, StandardCharsets.UTF_8)) {
            String l = line.strip();
            boolean host = !l.isEmpty() && !l.startsWith("#") && !l.startsWith("@") && !l.matches("\\d+/.*");
            sb.append(host ? jobs + "/" + l : l).append('\n');
        }
        Path file = dir.toAbsolutePath().resolve("sshloginfile");
        Files.writeString(file, sb.toString(), StandardCharsets.UTF_8);
        return List.of("--sshloginfile", file.toString(), "--jobs", "100%",
                "--ssh", root.toAbsolutePath().resolve("scripts/lib/tools/tournament-ssh").toString(), "--workdir", workdir);
    }

    /**
     * The environment of a parallel run on hosts: tournament-ssh's real ssh ({@code ssh}, null = ssh), its
     * failures file and the name of a job in it ({@code jobTag}, printf of parallel's sequence number), and
     * the remote shell.
     */
    public static void environment(Map<String, String> env, Path failures, String ssh, String jobTag) {
        env.put("PHALANX_TOURNAMENT_FAILURES", failures.toAbsolutePath().toString());
        env.put("PHALANX_TOURNAMENT_TAG", jobTag);
        if (ssh != null) env.put("PHALANX_TOURNAMENT_SSH", ssh);
        // parallel's remote worker runs each job with the shell it names here, else with the remote's $SHELL,
        // and with neither set (a CI job has no SHELL; so had the stand-in ssh of the tests) it runs nothing
        // and reports success (GNU parallel 20221122; match/README.md)
        env.put("PARALLEL_SHELL", "/bin/bash");
    }

    /** True when GNU parallel runs here (not moreutils' program of the same name). */
    public static boolean available() {
        try {
            Process p = new ProcessBuilder("parallel", "--version").redirectErrorStream(true).start();
            String v = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            return p.waitFor(20, TimeUnit.SECONDS) && p.exitValue() == 0 && v.contains("GNU parallel");
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}

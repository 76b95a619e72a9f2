package phalanx.match;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalLong;
import java.util.concurrent.TimeUnit;

/**
 * A command run in a session of its own ({@code setsid}), so that every process it starts, including
 * players it puts in the background before it exits, can be found (same session id in
 * {@code /proc/PID/stat}) and stopped by PID, and nothing else is touched. Linux only.
 */
public final class SessionProcess {
    private final Process process;
    private final long sid;
    private final String description;

    private SessionProcess(Process process, String description) {
        this.process = process;
        this.sid = process.pid();
        this.description = description;
    }

    /** Starts {@code argv} under setsid with its output (both streams) appended to {@code log}. */
    public static SessionProcess start(List<String> argv, Path workDir, Path log, String description) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add("setsid");
        cmd.addAll(argv);
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(workDir.toFile()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()))
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        SessionProcess p = new SessionProcess(pb.start(), description);
        return p;
    }

    /** A shell command line ({@code bash -c}) in its own session. */
    public static SessionProcess shell(String commandLine, Path workDir, Path log, String description) throws IOException {
        return start(List.of("bash", "-c", commandLine), workDir, log, description);
    }

    public long pid() { return process.pid(); }
    public String description() { return description; }

    /** The exit code of the started command itself, if it has exited (its background children may live on). */
    public Integer exitCode() { return process.isAlive() ? null : process.exitValue(); }

    /** PIDs of the live processes in this session (zombies excluded). */
    public List<Long> members() { return sessionMembers(sid); }

    public boolean anyAlive() { return !members().isEmpty(); }

    /**
     * Stops every process of the session: SIGTERM (or {@code firstSignal}) to each by PID, then SIGKILL to
     * whatever is left after {@code graceMillis}. Returns how many processes had to be killed.
     */
    public int stop(String firstSignal, long graceMillis) {
        for (long pid : members()) signal(pid, firstSignal);
        long deadline = System.nanoTime() + graceMillis * 1_000_000L;
        while (System.nanoTime() < deadline && anyAlive()) sleep(100);
        int killed = 0;
        for (long pid : members()) {
            signal(pid, "KILL");
            killed++;
        }
        // SIGKILL takes effect asynchronously: on a loaded machine a killed process was still listed (CI, 2026-12-04)
        long gone = System.nanoTime() + 2_000_000_000L;
        while (killed > 0 && anyAlive() && System.nanoTime() < gone) sleep(20);
        try {
            process.waitFor(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return killed;
    }

    /** Sends one signal to one PID with kill(1): the JDK can only send TERM and KILL, the server wants INT. */
    static void signal(long pid, String signal) {
        try {
            new ProcessBuilder("kill", "-" + signal, Long.toString(pid)).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start().waitFor(2, TimeUnit.SECONDS);
        } catch (IOException e) {
            // kill(1) missing: fall back to what the JDK can send
            ProcessHandle.of(pid).ifPresent(h -> { if (signal.equals("KILL")) h.destroyForcibly(); else h.destroy(); });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The live (not zombie) processes whose session id is {@code sid}, read from /proc. */
    static List<Long> sessionMembers(long sid) {
        List<Long> pids = new ArrayList<>();
        File[] entries = new File("/proc").listFiles();
        if (entries == null) return pids;
        for (File e : entries) {
            String name = e.getName();
            if (name.isEmpty() || !Character.isDigit(name.charAt(0))) continue;
            try {
                String stat = Files.readString(e.toPath().resolve("stat"), StandardCharsets.ISO_8859_1);
                OptionalLong s = sessionOf(stat);
                if (s.isPresent() && s.getAsLong() == sid && !stat.substring(stat.lastIndexOf(')') + 2).startsWith("Z")) {
                    pids.add(Long.parseLong(name));
                }
            } catch (IOException | RuntimeException ignored) {
                // the process ended while we looked
            }
        }
        return pids;
    }

    /** The session id field of a /proc/PID/stat line; the command name may hold spaces and parentheses. */
    static OptionalLong sessionOf(String statLine) {
        int close = statLine.lastIndexOf(')');
        if (close < 0) return OptionalLong.empty();
        String[] f = statLine.substring(close + 1).trim().split("\\s+");
        // after the name: state ppid pgrp session ...
        if (f.length < 4) return OptionalLong.empty();
        try {
            return OptionalLong.of(Long.parseLong(f[3]));
        } catch (NumberFormatException e) {
            return OptionalLong.empty();
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

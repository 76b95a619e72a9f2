package phalanx.match;

import phalanx.comm.monitor.MatchState;
import phalanx.comm.monitor.MonitorConnection;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.comm.wire.WireException;
import phalanx.match.MatchResult.ServerInfo;
import phalanx.match.MatchResult.TeamResult;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Logger;
import java.util.zip.GZIPOutputStream;

/**
 * Runs one match: starts a server on its own ports, starts the two teams one after the other (the
 * first to connect plays left, and robots of two teams must not be created in the same cycle), kicks
 * off both halves through the monitor port, follows the game on the monitor stream, and stops every
 * process it started, by PID, whatever happens (also from {@link #abort}, which a Ctrl-C hook calls).
 */
public final class MatchRunner {
    private static final Logger LOG = Logger.getLogger(MatchRunner.class.getName());

    private final MatchConfig cfg;
    private final PrintStream progress;
    private final MatchFollower follower = new MatchFollower();
    private final AtomicBoolean aborted = new AtomicBoolean();
    private final AtomicBoolean finished = new AtomicBoolean();
    private volatile long lastMessageNanos = System.nanoTime();
    private volatile boolean streamEnded;
    private volatile ServerProcess server;
    private volatile MonitorConnection monitor;
    private final Team[] teams = new Team[2];
    private final long startNanos = System.nanoTime();
    private final String started = Instant.now().toString();
    private volatile boolean serverDiedDuringGame;
    private volatile boolean monitorConnected;
    private volatile String abortReason = "interrupted";
    private volatile long kickOffNanos;
    private volatile long endNanos;
    private MatchResult result;

    /** A team while the match runs. */
    private static final class Team {
        final TeamCommand command;
        final Path log;
        final Path dir;
        volatile SessionProcess process;
        volatile Side side;
        volatile Double processesGoneAt;
        volatile String startError;
        volatile boolean startFailed;     // could not start, or its command failed: never allowed to be empty

        Team(TeamCommand command, Path root) {
            this.command = command;
            this.dir = root.resolve(command.label());
            this.log = root.resolve(command.label() + ".log");
        }
    }

    public MatchRunner(MatchConfig cfg, PrintStream progress) {
        this.cfg = cfg;
        this.progress = progress;
        teams[0] = new Team(cfg.first(), cfg.dir());
        teams[1] = new Team(cfg.second(), cfg.dir());
        if (cfg.first().label().equals(cfg.second().label())) {
            throw new IllegalArgumentException("both teams are called " + cfg.first().label() + ": give them different names");
        }
    }

    /** Runs the match to its end (or failure) and returns the result; it is also written to {@code cfg.out()}. */
    public MatchResult run() {
        String reason = null;
        try {
            Files.createDirectories(cfg.dir());
            reason = play();
        } catch (IOException e) {
            reason = e.getMessage();
        } catch (RuntimeException e) {
            LOG.warning("match failed: " + e);
            reason = "internal error: " + e;
        } finally {
            if (aborted.get() && reason == null) reason = abortReason;
            finish(reason);
        }
        return result;
    }

    /**
     * True once this match's server answered on its monitor port. False after {@link #run} means no game
     * could be played on this machine (no server, ports taken, the server exited at start), not a game result.
     */
    public boolean serverRan() { return monitorConnected; }

    /** Stops the match from another thread (Ctrl-C): every process is stopped and the result written. */
    public void abort(String why) {
        abortReason = why;
        aborted.set(true);
        finish(why);
    }

    private String play() throws IOException {
        server = ServerProcess.start(cfg.server(), cfg.dir());
        say("server pid %d on agent port %d, monitor port %d%s", server.pid(), cfg.server().agentPort(),
                cfg.server().monitorPort(), cfg.server().sync() ? " (agent-sync mode)" : "");
        String err = connectMonitor();
        if (err != null) return err;

        for (Team t : teams) {
            if (aborted.get()) return abortReason;
            int before = follower.presentCount();
            int[] presentBefore = {follower.present(Side.LEFT).size(), follower.present(Side.RIGHT).size()};
            startTeam(t);
            waitForPlayers(t, before, presentBefore);
            if (!server.alive()) return "server died while " + t.command.label() + " connected (exit " + server.exitCode() + ")";
            if (streamEnded) return "monitor stream ended while " + t.command.label() + " connected";
            double silent = (System.nanoTime() - lastMessageNanos) / 1e9;
            if (silent > cfg.stall()) {
                return "server stalled while " + t.command.label() + " connected: no monitor message for " + (int) silent + " s";
            }
        }
        for (Team t : teams) {
            if (t.side == null && !(cfg.allowEmpty() && !t.startFailed)) return "team " + t.command.label() + " has no players on the field"
                    + (t.startError != null ? " (" + t.startError + ")" : "");
        }
        say("%s left (%d players), %s right (%d players)", label(Side.LEFT), follower.present(Side.LEFT).size(),
                label(Side.RIGHT), follower.present(Side.RIGHT).size());
        pause(cfg.settle());

        for (int half = 1; half <= cfg.server().halves(); half++) {
            if (half == 2) {
                String e = waitFor(() -> follower.state().half() == 2 && follower.state().playMode() == PlayMode.BEFORE_KICK_OFF
                        || follower.gameOver(), "the second half");
                if (e != null) return e;
                if (follower.gameOver()) break;
                pause(cfg.settle());
            }
            String side = half == 1 ? "Left" : "Right";
            monitor.kickOff(side);
            if (half == 1) kickOffNanos = System.nanoTime();
            say("half %d: kick-off %s at game time %.1f", half, side, follower.state().time());
            if (half == 1 && cfg.server().halves() == 2) {
                String e = waitFor(() -> follower.state().half() == 2 || follower.gameOver(), "the end of the first half");
                if (e != null) return e;
            }
        }
        String e = waitFor(follower::gameOver, "the end of the game");
        if (e != null) return e;
        endNanos = System.nanoTime();
        MatchState s = follower.state();
        say("game over at %.1f: %s %d:%d %s", s.time(), label(Side.LEFT), s.scoreLeft(), s.scoreRight(), label(Side.RIGHT));
        return null;
    }

    private String connectMonitor() {
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (System.nanoTime() < deadline && !aborted.get()) {
            if (!server.alive()) return "server exited at start (exit " + server.exitCode() + "); see " + server.log();
            try {
                monitor = MonitorConnection.connect("127.0.0.1", cfg.server().monitorPort(), 1000);
                monitorConnected = true;
                Thread reader = new Thread(this::readStream, "monitor-reader");
                reader.setDaemon(true);
                reader.start();
                return null;
            } catch (WireException e) {
                pause(0.5);
            }
        }
        return aborted.get() ? abortReason : "no monitor port " + cfg.server().monitorPort() + " after 30 s; see " + server.log();
    }

    /** Follows the monitor stream and records it, one message a line, in monitor.log.gz (scripts/phalanx stats game). */
    private void readStream() {
        Writer log = openMonitorLog();
        try {
            while (!finished.get()) {
                String m = monitor.next();
                lastMessageNanos = System.nanoTime();
                follower.accept(m);
                log = record(log, m);
            }
        } catch (IOException e) {
            if (!finished.get()) LOG.info("monitor stream ended: " + e.getMessage());
        } finally {
            streamEnded = true;
            if (log != null) {
                try { log.close(); } catch (IOException e) { LOG.warning("monitor log: " + e.getMessage()); }
            }
        }
    }

    private Writer openMonitorLog() {
        Path p = monitorLog(cfg.dir());
        try {
            return new BufferedWriter(new OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(p)), StandardCharsets.ISO_8859_1));
        } catch (IOException e) {
            LOG.warning("cannot record the monitor stream in " + p + ": " + e.getMessage() + " (the match goes on)");
            return null;
        }
    }

    /** Writes one message; on a write error the recording stops and the match goes on. */
    private static Writer record(Writer log, String message) {
        if (log == null) return null;
        try {
            log.write(message.indexOf('\n') < 0 ? message : message.replace('\n', ' '));
            log.write('\n');
            return log;
        } catch (IOException e) {
            LOG.warning("monitor log: " + e.getMessage() + "; recording stopped");
            try { log.close(); } catch (IOException ignored) { }
            return null;
        }
    }

    /** Where a match's monitor stream is recorded. */
    static Path monitorLog(Path matchDir) { return matchDir.resolve("monitor.log.gz"); }

    private void startTeam(Team t) {
        try {
            Files.createDirectories(t.dir);
            String cmd = t.command.expand("127.0.0.1", cfg.server().agentPort(), t.dir.toString());
            Files.writeString(t.log, "# " + cmd + "\n");
            t.process = SessionProcess.shell(cmd, cfg.workDir(), t.log, t.command.label());
            say("started %s (session %d): %s", t.command.label(), t.process.pid(), cmd);
        } catch (IOException e) {
            t.startError = "cannot start: " + e.getMessage();
            t.startFailed = true;
            say("%s: %s", t.command.label(), t.startError);
        }
    }

    /**
     * Waits until the team has all its players on the field, or none joined for {@code connectQuiet}
     * seconds after the first, or {@code connectTimeout} passed, or its processes are all gone.
     */
    private void waitForPlayers(Team t, int before, int[] presentBefore) {
        if (t.process == null) return;
        long start = System.nanoTime();
        long lastChange = start;
        int last = before;
        while (!aborted.get() && server.alive() && !streamEnded) {
            int now = follower.presentCount();
            if (now != last) {
                last = now;
                lastChange = System.nanoTime();
            }
            if (now - before >= cfg.players()) break;
            double sinceStart = (System.nanoTime() - start) / 1e9, quiet = (System.nanoTime() - lastChange) / 1e9;
            if (now > before && quiet > cfg.connectQuiet()) break;
            if (sinceStart > cfg.connectTimeout()) break;
            if (!t.process.anyAlive() && quiet > 3) break; // nothing left that could still connect
            if ((System.nanoTime() - lastMessageNanos) / 1e9 > cfg.stall()) break; // the server hangs
            pause(0.2);
        }
        // The team's side: the side that gained players while it connected.
        Team other = teams[0] == t ? teams[1] : teams[0];
        for (Side side : Side.values()) {
            if (other.side != side && follower.present(side).size() > presentBefore[side.ordinal()]) {
                t.side = side;
                break;
            }
        }
        Integer exit = t.process.exitCode();
        if (t.side == null) {
            t.startFailed = exit != null && exit != 0;
            t.startError = exit != null && exit != 0 ? "start command exited with " + exit + " and no player connected"
                    : "no player connected in " + (int) cfg.connectTimeout() + " s";
        }
        say("%s: %d players on the %s%s", t.command.label(), follower.presentCount() - before,
                t.side == null ? "field" : t.side.name().toLowerCase(), exit != null ? ", start command exited with " + exit : "");
    }

    private interface Condition { boolean holds(); }

    /** Waits for the condition while checking for abort, server death, a stalled stream and the wall limit. */
    private String waitFor(Condition c, String what) {
        long lastCheck = 0;
        while (!c.holds()) {
            if (aborted.get()) return abortReason;
            if (streamEnded || !server.alive()) {
                pause(0.5);
                serverDiedDuringGame = true;
                return "server died before " + what + (server.exitCode() != null ? " (exit " + server.exitCode() + ")" : "")
                        + "; see " + server.log();
            }
            double silent = (System.nanoTime() - lastMessageNanos) / 1e9;
            if (silent > cfg.stall()) return "server stalled: no monitor message for " + (int) silent + " s before " + what;
            double wall = (System.nanoTime() - startNanos) / 1e9;
            if (wall > cfg.maxWall()) return "wall-clock limit of " + (int) cfg.maxWall() + " s reached before " + what;
            if (System.nanoTime() - lastCheck > 2_000_000_000L) {
                lastCheck = System.nanoTime();
                for (Team t : teams) {
                    if (t.processesGoneAt == null && t.process != null && !t.process.anyAlive()) {
                        t.processesGoneAt = follower.state().time();
                        say("%s: all its processes have exited (game time %.1f)", t.command.label(), t.processesGoneAt);
                    }
                }
            }
            pause(0.1);
        }
        return null;
    }

    private synchronized void finish(String reason) {
        if (!finished.compareAndSet(false, true)) return;
        if (reason != null) say("match not completed: %s", reason);
        for (Team t : teams) {
            if (t.process != null) {
                if (t.processesGoneAt == null && !t.process.anyAlive() && follower.state().time() > 0) t.processesGoneAt = follower.state().time();
                int killed = t.process.stop("TERM", 5000);
                if (killed > 0) say("%s: %d process(es) needed SIGKILL", t.command.label(), killed);
            }
        }
        if (monitor != null) monitor.close();
        if (server != null) {
            if (!server.alive() && reason == null) serverDiedDuringGame = true;
            server.stop();
        }
        result = buildResult(reason);
        try {
            Files.createDirectories(cfg.out().toAbsolutePath().getParent());
            result.write(cfg.out());
            say("result in %s", cfg.out());
        } catch (IOException e) {
            say("cannot write %s: %s", cfg.out(), e.getMessage());
        }
    }

    private MatchResult buildResult(String reason) {
        MatchState s = follower.state();
        boolean completed = reason == null && follower.gameOver();
        if (reason == null && !completed) reason = "the game did not reach GameOver";
        // Left and right as the server had them; a team that never got a side takes the free slot.
        TeamResult[] bySide = new TeamResult[2];
        for (Team t : teams) if (t.side != null) bySide[t.side.ordinal()] = teamResult(t, t.side);
        for (Team t : teams) {
            if (t.side == null) bySide[bySide[0] == null ? 0 : 1] = teamResult(t, null);
        }
        ServerProcess sv = server;
        ServerInfo info = new ServerInfo(cfg.server().agentPort(), cfg.server().monitorPort(), cfg.server().sync(),
                cfg.server().realTime(), cfg.dir().resolve("server.log").toString(), sv == null ? null : sv.exitCode(),
                serverDiedDuringGame);
        Double play = kickOffNanos == 0 ? null : Math.round(((endNanos != 0 ? endNanos : System.nanoTime()) - kickOffNanos) / 1e8) / 10.0;
        return new MatchResult(completed, reason, started, Math.round((System.nanoTime() - startNanos) / 1e8) / 10.0, play, info,
                follower.halfTime(), cfg.server().halves(), s.time(), bySide[0], bySide[1], follower.goals(),
                follower.timeline(), follower.rosterEvents());
    }

    private TeamResult teamResult(Team t, Side side) {
        Integer exit = t.process == null ? null : t.process.exitCode();
        if (side == null) {
            String status = t.process == null ? "not-started" : TeamResult.status(0, 0, cfg.players(), 0, exit);
            return new TeamResult(t.command.label(), null, t.command.template(), null, 0, status, exit, List.of(),
                    rangeList(cfg.players()), List.of(), t.processesGoneAt, t.log.toString());
        }
        List<Integer> seen = List.copyOf(follower.everSeen(side));
        List<Integer> never = follower.neverConnected(side, cfg.players());
        List<Integer> gone = follower.disconnected(side);
        int score = side == Side.LEFT ? follower.state().scoreLeft() : follower.state().scoreRight();
        String status = TeamResult.status(seen.size(), follower.present(side).size(), never.size(), gone.size(), exit);
        return new TeamResult(t.command.label(), follower.teamName(side), t.command.template(), side.name().toLowerCase(),
                score, status, exit, seen, never, gone, t.processesGoneAt, t.log.toString());
    }

    private static List<Integer> rangeList(int n) {
        return java.util.stream.IntStream.rangeClosed(1, n).boxed().toList();
    }

    private String label(Side side) {
        for (Team t : teams) if (t.side == side) return t.command.label();
        String n = follower.teamName(side);
        return n == null ? "-" : n;
    }

    private void say(String format, Object... args) {
        progress.printf("match: " + format + "%n", args);
        progress.flush();
    }

    private static void pause(double seconds) {
        try {
            Thread.sleep((long) (seconds * 1000));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

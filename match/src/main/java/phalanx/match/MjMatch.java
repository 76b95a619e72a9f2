package phalanx.match;

import phalanx.match.MatchResult.Goal;
import phalanx.match.MatchResult.ModeChange;
import phalanx.match.MatchResult.RosterEvent;
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
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.zip.GZIPOutputStream;

/**
 * One match on rcssservermj (docs/rcssservermj.md): a server run per half (the server plays one phase and ends
 * in GameOver), each on 127.0.0.1, headless, agent-sync without real time; the two teams started one after the
 * other (the first plays left), the kick-off given through the monitor port, progress (game time, score) printed,
 * the monitor stream recorded in each half's folder, and every process stopped by PID at the end, also from
 * {@link #abort} (Ctrl-C). The result is the same JSON as {@link MatchRunner}'s.
 */
public final class MjMatch {
    /** {@code halfTime} at most the rule book's 300 s: the server is started that much before the half's end. */
    public record Config(Path server, TeamCommand left, TeamCommand right, int agentPort, int monitorPort,
                         double halfTime, int halves, int players, double connectTimeout, Path dir, Path out) {
        public static final double RULE_HALF = 300;   // the ssim rule book, games/soccer/soccer_rules.py

        public Config {
            if (halves != 1 && halves != 2) throw new IllegalArgumentException("halves must be 1 or 2, got " + halves);
            if (!(halfTime > 0 && halfTime <= RULE_HALF))
                throw new IllegalArgumentException("half time on rcssservermj must be 1-300 s (its ssim rule book), got " + halfTime);
            if (left.label().equals(right.label())) throw new IllegalArgumentException("both teams are called " + left.label());
        }
    }

    private static final double PROGRESS_EVERY = 30;
    private static final long STALL_NANOS = 60_000_000_000L;

    private final Config cfg;
    private final PrintStream progress;
    private final AtomicBoolean aborted = new AtomicBoolean();
    private final AtomicBoolean done = new AtomicBoolean();
    private final long startNanos = System.nanoTime();
    private final String started = Instant.now().toString();
    private final List<SessionProcess> processes = new ArrayList<>();
    private final List<Goal> goals = new ArrayList<>();
    private final List<ModeChange> modes = new ArrayList<>();
    private final List<RosterEvent> roster = new ArrayList<>();
    private final Set<String> teamNames = new LinkedHashSet<>();
    private volatile MjServerProcess server;
    private volatile String abortReason = "interrupted";
    private int scoreLeft, scoreRight;
    private String lastMode;
    private double gameTime;
    private Long kickOffNanos;
    /** Per side (0 left, 1 right): uniform numbers that joined, that left, that are on the field now. */
    private final List<Set<Integer>> connected = sides(), disconnected = sides(), presentAtEnd = sides();
    private MatchResult result;

    public MjMatch(Config cfg, PrintStream progress) {
        this.cfg = cfg;
        this.progress = progress;
    }

    private static List<Set<Integer>> sides() { return List.of(new TreeSet<>(), new TreeSet<>()); }

    public MatchResult run() {
        String reason;
        try {
            Files.createDirectories(cfg.dir());
            reason = null;
            for (int half = 1; half <= cfg.halves() && reason == null; half++) reason = playHalf(half);
        } catch (IOException e) {
            reason = e.getMessage();
        } catch (RuntimeException e) {
            reason = "internal error: " + e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            reason = "interrupted";
        }
        if (aborted.get() && reason == null) reason = abortReason;
        finish(reason);
        return result;
    }

    /** Ctrl-C: stop everything now and write the result. */
    public void abort(String why) {
        abortReason = why;
        aborted.set(true);
        finish(why);
    }

    private String playHalf(int half) throws IOException, InterruptedException {
        Path dir = cfg.dir().resolve("half-" + half);
        double start = half * Config.RULE_HALF - cfg.halfTime();
        MjServerProcess.Settings s = new MjServerProcess.Settings(cfg.agentPort(), cfg.monitorPort(), true, false, half - 1,
                start == (half - 1) * Config.RULE_HALF ? Double.NaN : start);
        try {
            MjServerProcess.startReady(cfg.server(), s, dir, 90_000, started -> server = started,
                    why -> say("half %d: rcssservermj not ready (%s); starting it again", half, why));
        } catch (IOException e) {
            return e.getMessage();
        }
        say("half %d: rcssservermj pid %d on agent port %d, monitor port %d (agent-sync, no real time)", half,
                server.pid(), s.agentPort(), s.monitorPort());
        MjMonitor follower = new MjMonitor();
        long[] lastMessage = {System.nanoTime()};
        Writer log = new BufferedWriter(new OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(dir.resolve("monitor.log.gz"))),
                StandardCharsets.ISO_8859_1));
        server.onMonitorMessage(m -> follow(m, follower, log, lastMessage));
        try {
            int joinedBefore = 0;
            TeamCommand[] order = {cfg.left(), cfg.right()};
            for (TeamCommand t : order) {
                if (aborted.get()) return abortReason;
                Path tdir = dir.resolve(t.label());
                Files.createDirectories(tdir);
                processes.add(SessionProcess.shell(t.expand("127.0.0.1", s.agentPort(), tdir.toString()), Path.of(System.getProperty("user.dir")),
                        dir.resolve(t.label() + ".log"), t.label()));
                int want = joinedBefore + cfg.players();
                String e = waitFor(() -> joined() >= want, cfg.connectTimeout(), t.label() + "'s " + cfg.players() + " players", lastMessage);
                if (e != null) return e + " (" + joined() + " of " + want + " players joined; see " + dir.resolve(t.label() + ".log") + ")";
                joinedBefore = want;
            }
            say("half %d: %s left, %s right, %d players each", half, cfg.left().label(), cfg.right().label(), cfg.players());
            Thread.sleep(2000);   // let the last beams land
            server.command("(kickOff " + (half == 1 ? "Left" : "Right") + ")");
            if (kickOffNanos == null) kickOffNanos = System.nanoTime();
            double[] nextReport = {0};
            String e = waitFor(() -> {
                MjMonitor.State st = follower.state();
                if (st == null) return false;
                double played = st.time() - (half - 1) * Config.RULE_HALF - (Config.RULE_HALF - cfg.halfTime());
                if (played >= nextReport[0]) {
                    say("half %d: %5.1f s  %s %d:%d %s  (%s)", half, Math.max(0, played), cfg.left().label(), st.scoreLeft(),
                            st.scoreRight(), cfg.right().label(), st.playMode());
                    nextReport[0] += PROGRESS_EVERY;
                }
                return st.gameOver();
            }, 1e9, "the end of half " + half, lastMessage);
            if (e != null) return e;
            rosterAtEnd(half);
            return null;
        } finally {
            stopProcesses();
            server.stop();
            synchronized (log) { log.close(); }
        }
    }

    private int joined() {
        return (int) readLog().stream().filter(r -> r[2].equals("joined")).count();
    }

    private List<String[]> readLog() {
        try {
            return MjMonitor.rosterLines(Files.readAllLines(server.log(), StandardCharsets.ISO_8859_1));
        } catch (IOException e) {
            return List.of();
        }
    }

    /** Who joined and left in this half, from the server log; the first team to join is the left. */
    private void rosterAtEnd(int half) {
        List<String> names = new ArrayList<>();
        presentAtEnd.forEach(Set::clear);   // a new server each half: everyone joins again
        for (String[] r : readLog()) {
            if (!names.contains(r[0])) names.add(r[0]);
            int side = names.indexOf(r[0]);
            if (side > 1) continue;
            int unum = Integer.parseInt(r[1]);
            boolean joined = r[2].equals("joined");
            roster.add(new RosterEvent(gameTime, half, side == 0 ? "left" : "right", unum, joined));
            (joined ? connected : disconnected).get(side).add(unum);
            if (joined) presentAtEnd.get(side).add(unum); else presentAtEnd.get(side).remove(unum);
        }
        teamNames.addAll(names);
    }

    /** One monitor message (on the server's monitor thread): recorded, and the score and play modes followed. */
    private void follow(String m, MjMonitor follower, Writer log, long[] lastMessage) {
        lastMessage[0] = System.nanoTime();
        try {
            synchronized (log) { log.write(m.replace('\n', ' ')); log.write('\n'); }
        } catch (IOException e) {
            // closed at the end of the half, or the disk is full: the game goes on unrecorded
        }
        MjMonitor.State st = follower.accept(m);
        if (st == null) return;
        synchronized (this) {
            gameTime = st.time();
            if (st.scoreLeft() > scoreLeft || st.scoreRight() > scoreRight) {
                String side = st.scoreLeft() > scoreLeft ? "left" : "right";
                scoreLeft = st.scoreLeft();
                scoreRight = st.scoreRight();
                goals.add(new Goal(st.time(), st.half(), side, side.equals("left") ? cfg.left().label() : cfg.right().label(),
                        scoreLeft, scoreRight));
                say("GOAL %s at %.1f: %d:%d", side, st.time(), scoreLeft, scoreRight);
            }
            if (!st.playMode().equals(lastMode)) modes.add(new ModeChange(st.time(), st.half(), lastMode = st.playMode()));
        }
    }

    private interface Condition { boolean met(); }

    /** Null when met; otherwise why not (abort, dead server, silent monitor, timeout). */
    private String waitFor(Condition c, double seconds, String what, long[] lastMessage) throws InterruptedException {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        while (!c.met()) {
            if (aborted.get()) return abortReason;
            if (!server.alive()) return "rcssservermj died while waiting for " + what + "; see " + server.log();
            if (System.nanoTime() - lastMessage[0] > STALL_NANOS) return "rcssservermj stalled (no monitor message for 60 s) while waiting for " + what;
            if (System.nanoTime() > deadline) return "no " + what + " within " + (int) seconds + " s";
            Thread.sleep(100);
        }
        return null;
    }

    private synchronized void stopProcesses() {
        for (SessionProcess p : processes) p.stop("TERM", 5_000);
        processes.clear();
    }

    private synchronized void finish(String reason) {
        if (!done.compareAndSet(false, true)) return;
        stopProcesses();
        if (server != null) server.stop();
        double wall = (System.nanoTime() - startNanos) / 1e9;
        Double playWall = kickOffNanos == null ? null : (System.nanoTime() - kickOffNanos) / 1e9;
        List<String> names = new ArrayList<>(teamNames);
        TeamResult l = team(0, cfg.left(), names, scoreLeft), r = team(1, cfg.right(), names, scoreRight);
        ServerInfo info = new ServerInfo(cfg.agentPort(), cfg.monitorPort(), true, false,
                server == null ? null : server.log().toString(), null, false);
        result = new MatchResult(reason == null, reason, started, wall, playWall, info, cfg.halfTime(), cfg.halves(), gameTime,
                l, r, List.copyOf(goals), List.copyOf(modes), List.copyOf(roster));
        try {
            result.write(cfg.out());
        } catch (IOException e) {
            say("cannot write %s: %s", cfg.out(), e.getMessage());
        }
        if (reason == null) say("game over: %s %d:%d %s (result %s)", cfg.left().label(), scoreLeft, scoreRight, cfg.right().label(), cfg.out());
        else say("match ended early: %s (result %s)", reason, cfg.out());
    }

    private TeamResult team(int side, TeamCommand t, List<String> names, int score) {
        List<Integer> never = new ArrayList<>();
        for (int n = 1; n <= cfg.players(); n++) if (!connected.get(side).contains(n)) never.add(n);
        String status = TeamResult.status(connected.get(side).size(), presentAtEnd.get(side).size(), never.size(), disconnected.get(side).size(), null);
        return new TeamResult(t.label(), side < names.size() ? names.get(side) : null, t.template(), side == 0 ? "left" : "right",
                score, status, null, List.copyOf(connected.get(side)), never, List.copyOf(disconnected.get(side)), null,
                cfg.dir().resolve("half-1").resolve(t.label() + ".log").toString());
    }

    private void say(String fmt, Object... args) {
        progress.printf("match: " + fmt + "%n", args);
        progress.flush();
    }
}

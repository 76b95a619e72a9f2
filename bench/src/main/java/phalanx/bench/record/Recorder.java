package phalanx.bench.record;

import phalanx.comm.monitor.MatchState;
import phalanx.comm.monitor.MonitorHeader;
import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Side;
import phalanx.comm.recording.GroundTruth;
import phalanx.comm.wire.ServerConnection;
import phalanx.match.ServerProcess;
import phalanx.motion.MotionLibrary;
import phalanx.motion.walk.Odometry;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.zip.GZIPOutputStream;

/**
 * scripts/phalanx bench record (issue 19): stages one {@link Scenario} in a private rcssserver3d (agent-sync, real
 * time on, a monitor picture every cycle) and writes the recorded robot's streams in the shared recordings' format
 * (../shared/recordings/README.md): {@code X_perceptors.txt.gz}, {@code X_effectors.txt.gz}, {@code X_groundtruth.txt.gz}
 * and {@code X_trainer.txt}. Every robot is driven from this one thread, one message at a time, so the server, which
 * waits for every {@code (syn)}, never steps ahead of the ground truth.
 *
 * <p>Pairing: in a cycle the server steps, sends the monitor picture, then the next perceptions (the recordings
 * README, "Pairing"); so when the recorded robot's message has arrived its picture has too, and the monitor is
 * drained right then. A {@code (reqfullstate)} every cycle makes every picture a full scene graph (no 5 mm delta
 * filter). Checked on every line where the game clock runs: the {@code GS} game time equals the picture's.
 */
public final class Recorder {
    static final String USAGE = """
            usage: scripts/phalanx bench record SCENARIO --dir DIR [--name X] [--type T] [--side left|right] [--port P]
              SCENARIO: walk-head, turn-head, ball-roll, crowd, fall (bench/README.md "The recorder")
              starts its own rcssserver3d ($RCSSSERVER3D or rcssserver3d on PATH; agent port P, default the first
              free pair from 4600 to 4799, monitor P+200), stages the scenario and writes DIR/X_{perceptors,effectors,groundtruth}.txt.gz
              DIR/X_odometry.txt.gz and DIR/X_trainer.txt (X defaults to the scenario's name; the server's log goes to DIR/X-server/).""";

    /**
     * The first line of {@code X_odometry.txt.gz} (not in the shared format): then one line per perceptor line, the
     * walk's own motion in the cycle of the reply to that line, as the agent passes it to {@code BeliefStore.odometry}.
     */
    static final String ODOMETRY_HEADER = "# forward_m left_m turn_deg: the walk's commanded motion in the cycle of the reply to perceptor line i (BeliefStore.odometry after update i); 0 0 0 outside the walk";

    /** The monitor port is the agent port + 200: agent ports 4600-4799, monitor ports 4800-4999 (games use 3100-3700). */
    static final int MONITOR_OFFSET = 200;

    record Options(String scenario, Path dir, String name, int type, boolean right, int port) {}

    /** Parses the flags; a bad one throws IllegalArgumentException naming it. */
    static Options parse(String... args) {
        String scenario = null, name = null;
        Path dir = null;
        int type = -1, port = 0;
        boolean right = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("-h") || a.equals("--help")) throw new IllegalArgumentException("help");
            if (!a.startsWith("--")) {
                if (scenario != null) throw new IllegalArgumentException("one scenario only, got '" + scenario + "' and '" + a + "'");
                scenario = a;
                continue;
            }
            if (i + 1 >= args.length) throw new IllegalArgumentException(a + " needs a value");
            String v = args[++i];
            try {
                switch (a) {
                    case "--dir" -> dir = Path.of(v);
                    case "--name" -> {
                        if (!v.matches("[A-Za-z0-9_.-]+")) throw new IllegalArgumentException("--name takes letters, digits, '_', '.', '-', got '" + v + "'");
                        name = v;
                    }
                    case "--type" -> type = Integer.parseInt(v);
                    case "--port" -> port = Integer.parseInt(v);
                    case "--side" -> {
                        if (!v.equals("left") && !v.equals("right")) throw new IllegalArgumentException("--side must be left or right, got '" + v + "'");
                        right = v.equals("right");
                    }
                    default -> throw new IllegalArgumentException("unknown option " + a);
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(a + " needs a number, got '" + v + "'");
            }
        }
        if (scenario == null) throw new IllegalArgumentException("no scenario (one of " + String.join(", ", Scenario.NAMES) + ")");
        if (!Scenario.NAMES.contains(scenario)) throw new IllegalArgumentException("unknown scenario '" + scenario + "' (one of " + String.join(", ", Scenario.NAMES) + ")");
        if (dir == null) throw new IllegalArgumentException("--dir is required");
        if (type < -1 || type > 4) throw new IllegalArgumentException("--type must be 0-4, got " + type);
        if (port != 0 && (port < 1024 || port > 65335)) throw new IllegalArgumentException("--port must be 1024-65335, got " + port);
        return new Options(scenario, dir, name == null ? scenario : name, type, right, port);
    }

    /** What a run found about its own pairing, printed at the end (and a reason to fail when it is wrong). */
    static final class Tally {
        int lines, clockLines, clockMismatches, noPicture, malformed, extraPictures;
        String firstMismatch;
    }

    public static void main(String[] args) throws Exception {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            boolean help = e.getMessage().equals("help");
            if (!help) System.err.println("record: " + e.getMessage());
            System.err.println(USAGE);
            System.exit(help ? 0 : 2);
            return;
        }
        System.exit(run(o));
    }

    static int run(Options o) throws IOException {
        Scenario sc = Scenario.of(o.scenario(), o.right());
        int type = o.type() >= 0 ? o.type() : sc.defaultType();
        Path root = Path.of(System.getProperty("phalanx.root", ".")).toAbsolutePath().normalize();
        Files.createDirectories(o.dir());
        Path serverDir = o.dir().resolve(o.name() + "-server");
        Files.createDirectories(serverDir);
        int port;
        try {
            port = o.port() != 0 ? o.port() : ServerProcess.freePortPair(4600, 200, MONITOR_OFFSET);
        } catch (IllegalStateException e) {
            System.err.println("record: " + e.getMessage());
            return 3;
        }
        ServerProcess server;
        try {
            // real time on, as the shared recordings: `now` stays small and the clock exact; $monitorStep 0.02: a picture per cycle
            server = ServerProcess.start(new ServerProcess.Settings(port, port + MONITOR_OFFSET, true, true, 600, 1), serverDir, "$monitorStep = 0.02");
        } catch (IOException e) {
            System.err.println("record: " + e.getMessage());
            return 3;
        }
        Thread stop = new Thread(server::stop, "record-stop");
        Runtime.getRuntime().addShutdownHook(stop);
        List<Bot> bots = new ArrayList<>();
        try (ServerConnection mon = ServerConnection.connect("127.0.0.1", port + MONITOR_OFFSET, 30_000);
             Writer per = gz(o.dir().resolve(o.name() + "_perceptors.txt.gz"));
             Writer eff = gz(o.dir().resolve(o.name() + "_effectors.txt.gz"));
             Writer gt = gz(o.dir().resolve(o.name() + "_groundtruth.txt.gz"));
             Writer odo = gz(o.dir().resolve(o.name() + "_odometry.txt.gz"));
             Writer tr = Files.newBufferedWriter(o.dir().resolve(o.name() + "_trainer.txt"), StandardCharsets.US_ASCII)) {
            gt.write(GroundTruth.HEADER + "\n");
            odo.write(ODOMETRY_HEADER + "\n");
            tr.write("# now_of_last_perceptor_message_received  trainer_command_sent_on_monitor_port\n");
            Tally tally = record(o, sc, type, root, port, mon, bots, per, eff, gt, odo, tr);
            System.out.printf(Locale.ROOT, "record %s: %s, type %d, %s side, %d lines; game clock running on %d lines, %d where the GS time and the"
                            + " monitor's differ%s; %d lines without a monitor picture (torso nan), %d pictures more than one a cycle; %d malformed messages%n",
                    o.name(), sc.name(), type, o.right() ? "right" : "left", tally.lines, tally.clockLines, tally.clockMismatches,
                    tally.firstMismatch == null ? "" : " (first: " + tally.firstMismatch + ")", tally.noPicture, tally.extraPictures, tally.malformed);
            return tally.clockMismatches == 0 ? 0 : 1;
        } catch (IOException e) {
            System.err.println("record: " + e.getMessage() + " (server log: " + server.log() + ")");
            return 1;
        } finally {
            for (Bot b : bots) b.close();
            server.stop();
            Runtime.getRuntime().removeShutdownHook(stop);
        }
    }

    private static Writer gz(Path p) throws IOException {
        return new BufferedWriter(new OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(p)), StandardCharsets.ISO_8859_1));
    }

    private static Tally record(Options o, Scenario sc, int type, Path root, int port, ServerConnection mon, List<Bot> bots,
                                Writer per, Writer eff, Writer gt, Writer odo, Writer tr) throws IOException {
        Map<Integer, MotionLibrary> libraries = new HashMap<>();
        Side recSide = o.right() ? Side.RIGHT : Side.LEFT, otherSide = o.right() ? Side.LEFT : Side.RIGHT;
        // the team that connects first takes the left (recordings README, S6); one robot at a time, each once the
        // one before has had 3 messages (S5: robots created in the same cycle spawn on one spot and the server stalls)
        record Pending(String team, int unum, int type, Side side, Plan plan, boolean recorded) {}
        List<Pending> order = new ArrayList<>();
        Pending rec = new Pending(Scenario.RECORDED_TEAM, 1, type, recSide, sc.recorded(), true);
        if (!o.right()) order.add(rec);
        for (Scenario.Member m : sc.others()) order.add(new Pending(m.team(), m.unum(), m.type(), otherSide, m.plan(), false));
        if (o.right()) order.add(rec);

        MonitorScene scene = new MonitorScene();
        MonitorHeader header = new MonitorHeader();
        Picture picture = null;
        Tally tally = new Tally();
        Bot recorded = null;
        int next = 0;
        long lastProgress = System.currentTimeMillis();
        while (recorded == null || !recorded.done()) {
            if (next < order.size() && (bots.isEmpty() || bots.get(bots.size() - 1).received() >= 3)) {
                Pending p = order.get(next++);
                MotionLibrary lib = libraries.computeIfAbsent(p.type(), t -> {
                    try {
                        return MotionLibrary.load(root.resolve("motions"), t);
                    } catch (Exception e) {
                        throw new IllegalStateException("the motions under " + root.resolve("motions") + ": " + e.getMessage(), e);
                    }
                });
                Bot b = Bot.connect("127.0.0.1", port, p.team(), p.unum(), p.type(), p.side(), p.plan(), lib);
                bots.add(b);
                if (p.recorded()) {
                    recorded = b;
                    eff.write(b.sceneLine() + "\n");
                }
            }
            // one cycle: every robot that has had a message gets exactly one; a robot just connected may get its first
            List<Bot> waiting = new ArrayList<>();
            for (Bot b : bots) if (b.received() > 0) waiting.add(b);
            List<Bot> fresh = new ArrayList<>();
            for (Bot b : bots) if (b.received() == 0) fresh.add(b);
            while (!waiting.isEmpty() || !fresh.isEmpty()) {
                boolean progress = false;
                for (List<Bot> group : List.of(waiting, fresh)) {
                    for (int i = 0; i < group.size(); i++) {
                        Bot b = group.get(i);
                        if (!b.ready()) continue;
                        String text = b.read();
                        String joined = b.joinProblem();
                        if (joined != null) throw new IOException(joined);
                        if (b == recorded) {
                            // this message's picture was read after the message before it (null: the server skipped it)
                            if (recorded.received() == 1) picture = drain(mon, scene, header, recorded, 0, tally);
                            Picture mine = picture;
                            per.write(text + "\n");
                            line(gt, recorded, mine, tally);
                            List<String> cmds = sc.trainer().get(b.received());
                            if (cmds != null) {
                                for (String c : cmds) {
                                    mon.send(c);
                                    tr.write(String.format(Locale.ROOT, "%.2f %s%n", b.last().time(), c));
                                }
                            }
                            mon.send("(reqfullstate)");
                            // the server sends the next picture right after this message, before any reply (it acts on the
                            // replies to the message before): wait for it, so that the next line gets its own picture
                            picture = drain(mon, scene, header, recorded, PICTURE_WAIT_MILLIS, tally);
                            eff.write(b.reply() + "\n");
                            Odometry d = b.odometry();
                            odo.write(String.format(Locale.ROOT, "%.5f %.5f %.4f%n", d.forward(), d.left(), d.turnDeg()));
                        } else {
                            b.reply();
                        }
                        group.remove(i--);
                        progress = true;
                    }
                }
                if (progress) {
                    lastProgress = System.currentTimeMillis();
                    continue;
                }
                long idle = System.currentTimeMillis() - lastProgress;
                if (idle > 20_000) {
                    throw new IOException("no message from the server for 20 s (" + bots.size() + " robots connected, recorded robot at line "
                            + (recorded == null ? 0 : recorded.received()) + ")");
                }
                // a robot just connected gets its first message in this cycle or a later one: wait a little, then go on
                if (waiting.isEmpty() && idle > 300) break;
                mon.awaitData(1);
            }
        }
        tally.malformed = recorded.malformed();
        return tally;
    }

    /**
     * How long to wait for the picture that follows a message. The server sends it after stepping, without waiting for
     * any reply; it skips one in the cycle after a robot was created (recordings README), and then none comes.
     */
    static final long PICTURE_WAIT_MILLIS = 300;

    /** What a monitor picture says of the recorded robot: game time, play mode, torso (null: not in the scene), ball. */
    record Picture(double time, String playMode, MonitorScene.Pose torso, double[] ball) {}

    private static MatchState state = MatchState.INITIAL;

    /**
     * Waits up to {@code millis} for a monitor message and reads every one waiting; the picture after the last, or null
     * when none came. More than one at a time is counted ({@code extraPictures}): a sign the pairing slipped.
     */
    private static Picture drain(ServerConnection mon, MonitorScene scene, MonitorHeader header, Bot rec, long millis, Tally tally) throws IOException {
        if (!mon.awaitData(millis)) return null;
        int n = 0;
        do {
            mon.reader().next();
            String m = mon.reader().text();
            state = header.apply(state, m);
            try {
                scene.apply(m);
            } catch (IllegalArgumentException e) {
                System.err.println("record: a monitor message it could not read: " + e.getMessage());
            }
            n++;
        } while (mon.awaitData(0));
        if (n > 1 && rec.received() > 1) tally.extraPictures += n - 1;
        MonitorScene.Pose t = scene.torso(rec.unum, rec.side == Side.RIGHT ? "Right" : "Left");
        return new Picture(state.time(), state.playMode().wireName(), t, scene.ball());
    }

    /** The ground-truth line of the recorded robot's message just read. */
    private static void line(Writer gt, Bot rec, Picture pic, Tally tally) throws IOException {
        tally.lines++;
        Perception p = rec.last();
        double now = p == null ? Double.NaN : p.time();
        if (pic == null) {
            tally.noPicture++;
            // no picture for this cycle: nothing of it is known, not even the game time (the shared files write nan too;
            // the last picture's time would be one cycle old, a mismatch with the GS)
            gt.write(GroundTruth.format(now, Double.NaN, "nan", Double.NaN, Double.NaN, Double.NaN, null,
                    Double.NaN, Double.NaN, Double.NaN) + "\n");
            return;
        }
        MonitorScene.Pose t = pic.torso();
        double[] ball = pic.ball();
        gt.write(GroundTruth.format(now, pic.time(), pic.playMode(),
                t == null ? Double.NaN : t.x(), t == null ? Double.NaN : t.y(), t == null ? Double.NaN : t.z(), t == null ? null : t.r(),
                ball == null ? Double.NaN : ball[0], ball == null ? Double.NaN : ball[1], ball == null ? Double.NaN : ball[2]) + "\n");
        if (p != null && p.gameState() != null && pic.time() > 0 && p.gameState().gameTime() > 0) {
            tally.clockLines++;
            if (Math.abs(p.gameState().gameTime() - pic.time()) > 0.005) {
                tally.clockMismatches++;
                if (tally.firstMismatch == null)
                    tally.firstMismatch = String.format(Locale.ROOT, "line %d: GS %.2f, monitor %.2f", tally.lines, p.gameState().gameTime(), pic.time());
            }
        }
    }
}

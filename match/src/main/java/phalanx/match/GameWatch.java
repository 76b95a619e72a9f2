package phalanx.match;

import phalanx.match.Flags;
import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.monitor.MatchState;
import phalanx.comm.monitor.MonitorHeader;
import phalanx.comm.wire.ServerConnection;

import java.io.IOException;
import java.io.PrintStream;
import java.util.Locale;

/**
 * scripts/phalanx watch: a text monitor for reviewing a game. It joins a running server's monitor port and
 * prints, every {@code --every} seconds of game time, the play mode, the score, the ball and every robot
 * (x, y; {@code _} after a robot lying down), one line each. Read-only: it sends nothing but full-state
 * requests. It ends when the server closes the connection.
 */
public final class GameWatch {
    static final String USAGE = """
            usage: scripts/phalanx watch [--host 127.0.0.1] --monitor-port M [--every 2] [--players 11]
              prints one line per --every game seconds: time, play mode, score, ball, each robot's x,y
              (L1..L11, R1..R11; '_' after a robot whose torso is more than 60 degrees from upright)""";

    private final MonitorScene scene = new MonitorScene();
    private final MonitorHeader header = new MonitorHeader();
    private final int players;
    private MatchState state = MatchState.INITIAL;

    GameWatch(int players) { this.players = players; }

    /** Applies one monitor message; false when the scene could not be read (the message is skipped). */
    boolean apply(String message) {
        state = header.apply(state, message);
        try {
            scene.apply(message);
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /** The line for the current scene. */
    String line() {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "t=%6.1f %-14s %d:%d", state.time(),
                state.playMode(), state.scoreLeft(), state.scoreRight()));
        double[] ball = scene.ball();
        b.append(ball == null ? " ball=?" : String.format(Locale.ROOT, " ball=(%.2f,%.2f)", ball[0], ball[1]));
        for (String side : new String[] {"Left", "Right"}) {
            for (int u = 1; u <= players; u++) {
                MonitorScene.Pose p = scene.torso(u, side);
                if (p == null) continue;
                b.append(String.format(Locale.ROOT, " %c%d(%.1f,%.1f)%s", side.charAt(0), u, p.x(), p.y(), p.upZ() < 0.5 ? "_" : ""));
            }
        }
        return b.toString();
    }

    double time() { return state.time(); }

    public static void main(String[] argv) {
        String host = "127.0.0.1";
        int port = -1, players = 11;
        double every = 2;
        try {
            for (int i = 0; i < argv.length; i++) {
                String flag = argv[i];
                if (flag.equals("--help")) { System.out.println(USAGE); System.exit(0); }
                if (i + 1 >= argv.length) throw new IllegalArgumentException(flag + " needs a value");
                String v = argv[++i];
                switch (flag) {
                    case "--host" -> host = v;
                    case "--monitor-port" -> port = (int) Flags.number(flag, v, 1, 65535, true);
                    case "--every" -> every = Flags.number(flag, v, 0.02, 600, false);
                    case "--players" -> players = (int) Flags.number(flag, v, 1, 11, true);
                    default -> throw new IllegalArgumentException("game-watch: unknown flag " + flag);
                }
            }
            if (port < 0) throw new IllegalArgumentException("game-watch: --monitor-port is required");
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage() + "\n" + USAGE);
            System.exit(2);
            return;
        }
        System.exit(run(host, port, every, players, System.out));
    }

    static int run(String host, int port, double every, int players, PrintStream out) {
        GameWatch w = new GameWatch(players);
        try (ServerConnection monitor = ServerConnection.connect(host, port, 10_000)) {
            double next = Double.NEGATIVE_INFINITY;
            long messages = 0;
            while (true) {
                monitor.reader().next();
                if (!w.apply(monitor.reader().text())) System.err.println("game-watch: skipped a monitor message it could not read");
                // A partial scene drifts from the truth after a while (motion/README.md): ask for a full one now and then.
                if (++messages % 25 == 0) monitor.send("(reqfullstate)");
                if (w.time() >= next) {
                    out.println(w.line());
                    next = w.time() + every;
                }
            }
        } catch (IOException e) {
            System.err.println("game-watch: monitor connection ended: " + e.getMessage());
            return 0;
        }
    }
}

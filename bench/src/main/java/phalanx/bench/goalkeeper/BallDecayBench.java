package phalanx.bench.goalkeeper;

import phalanx.agent.goalkeeper.BallRoll;
import phalanx.comm.wire.ServerConnection;
import phalanx.comm.monitor.MonitorScene;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * scripts/phalanx bench ball-decay: measures how a rolling ball slows down in a running rcssserver3d, to check
 * {@link BallRoll}'s model v(t) = v0·e^(−k·t). Through the monitor port only (trainer commands and
 * the scene graph's ground truth; no player needed): PlayOn, then for each speed the ball is set
 * at (-8, ±0.5) with velocity (v0, 0, 0) and followed until it stops. For each run it prints the
 * distance rolled, k from that distance (v0 / d), and k from a least-squares fit of ln(speed)
 * over time while the speed is above 0.1 m/s, and the "rolling fraction": the speed at 0.5 s over
 * v0·e^(−k·0.5) (a ball set moving without spin slides first and rolls on with part of its speed;
 * 5/7 for an ideal sphere). The last line: {@code ball_decay_k=... (fit mean)}.
 * <p>{@code --lift VZ} launches every ball with an upward speed as well (a lofted kick): the lines then
 * also give the highest point and the distance at the first landing, which is what a strong kick
 * needs to know (motion/README.md "Kicks and dives").
 */
public final class BallDecayBench {
    private BallDecayBench() {}

    record Sample(double t, double x, double y, double z) {
        Sample(double t, double x, double y) { this(t, x, y, RADIUS); }
    }

    static final double RADIUS = 0.042;

    /** The command line: monitor host and port, start speeds (m/s), seconds followed per run, upward start speed. */
    record Options(String host, int port, double[] speeds, double seconds, double lift) {}

    /** Parses the flags; a bad one throws IllegalArgumentException naming it. */
    static Options parse(String... args) {
        String host = "127.0.0.1";
        int port = 3200;
        double[] speeds = {1, 2, 4, 6};
        double seconds = 8, lift = 0;
        for (int i = 0; i < args.length; i += 2) {
            String a = args[i];
            if (!a.equals("--host") && !a.equals("--monitor-port") && !a.equals("--speeds") && !a.equals("--seconds")
                    && !a.equals("--lift")) {
                throw new IllegalArgumentException("unknown option '" + a + "'");
            }
            if (i + 1 >= args.length) throw new IllegalArgumentException(a + " needs a value");
            String v = args[i + 1];
            try {
                switch (a) {
                    case "--host" -> host = v;
                    case "--monitor-port" -> port = Integer.parseInt(v);
                    case "--speeds" -> {
                        String[] p = v.split(",");
                        speeds = new double[p.length];
                        for (int k = 0; k < p.length; k++) speeds[k] = Double.parseDouble(p[k]);
                    }
                    case "--lift" -> lift = Double.parseDouble(v);
                    default -> seconds = Double.parseDouble(v);
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(a + " needs " + (a.equals("--monitor-port") ? "a whole number" : "numbers") + ", got '" + v + "'");
            }
        }
        if (port < 1 || port > 65535) throw new IllegalArgumentException("--monitor-port must be 1-65535, got " + port);
        for (double v : speeds) {
            if (!(v > 0 && v <= 20)) throw new IllegalArgumentException("--speeds must be within (0, 20] m/s, got " + v);
        }
        if (!(seconds > 0 && seconds <= 60)) throw new IllegalArgumentException("--seconds must be within (0, 60], got " + seconds);
        if (!(lift >= 0 && lift <= 20)) throw new IllegalArgumentException("--lift must be within [0, 20] m/s, got " + lift);
        return new Options(host, port, speeds, seconds, lift);
    }

    public static void main(String[] args) throws IOException {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("ball-decay: " + e.getMessage());
            System.exit(2);
            return;
        }
        try (ServerConnection mon = ServerConnection.connect(o.host(), o.port(), 10_000)) {
            MonitorScene scene = new MonitorScene();
            while (!scene.hasScene() || scene.ball() == null) next(mon, scene);
            mon.send("(playMode PlayOn)");
            double sumK = 0;
            for (int i = 0; i < o.speeds().length; i++) {
                double v0 = o.speeds()[i];
                List<Sample> run = roll(mon, scene, v0, o.lift(), i % 2 == 0 ? 0.5 : -0.5, o.seconds());
                double d = run.get(run.size() - 1).x() - run.get(0).x();
                double kFit = fit(run);
                sumK += kFit;
                double rolling = speedAt(run, 0.5) / (v0 * Math.exp(-kFit * 0.5));
                System.out.printf(Locale.ROOT, "v0=%.2f samples=%d distance_m=%.3f k_from_distance=%.3f k_fit=%.3f rolling_fraction=%.3f",
                        v0, run.size(), d, v0 / d, kFit, rolling);
                if (o.lift() > 0) {
                    System.out.printf(Locale.ROOT, " vz=%.2f top_m=%.3f first_landing_m=%.3f",
                            o.lift(), top(run), firstLanding(run));
                }
                System.out.println();
            }
            System.out.printf(Locale.ROOT, "ball_decay_k=%.3f%n", sumK / o.speeds().length);
        }
    }

    private static void next(ServerConnection mon, MonitorScene scene) throws IOException {
        mon.reader().next();
        scene.apply(mon.reader().text());
    }

    private static List<Sample> roll(ServerConnection mon, MonitorScene scene, double v0, double vz, double y, double seconds)
            throws IOException {
        mon.send(String.format(Locale.ROOT, "(ball (pos -8 %.1f 0.042)(vel %.3f 0 %.3f))", y, v0, vz));
        // Wait for the scene to show the ball on its new line (runs alternate y = ±0.5: a fast ball
        // is already well past x = -8 in the first picture).
        do next(mon, scene); while (Math.abs(scene.ball()[1] - y) > 0.05 || scene.ball()[0] > -6);
        List<Sample> out = new ArrayList<>();
        double t0 = scene.time();
        while (scene.time() - t0 < seconds) {
            double[] b = scene.ball();
            out.add(new Sample(scene.time(), b[0], b[1], b[2]));
            next(mon, scene);
        }
        return out;
    }

    /** The ball centre's highest point above the ground (m). */
    static double top(List<Sample> run) {
        double top = 0;
        for (Sample s : run) top = Math.max(top, s.z() - RADIUS);
        return top;
    }

    /**
     * Distance from the start where the ball first comes back to the ground after having risen 5 cm
     * (NaN if it never rose or never came down within the run).
     */
    static double firstLanding(List<Sample> run) {
        boolean up = false;
        for (Sample s : run) {
            if (!up && s.z() - RADIUS > 0.05) up = true;
            else if (up && s.z() - RADIUS < 0.01) return Math.hypot(s.x() - run.get(0).x(), s.y() - run.get(0).y());
        }
        return Double.NaN;
    }

    /** Mean speed over the 0.1 s after {@code after} seconds from the run's start; NaN if the run is shorter. */
    static double speedAt(List<Sample> run, double after) {
        double t0 = run.get(0).t();
        Sample a = null;
        for (Sample x : run) {
            if (a == null && x.t() - t0 >= after) a = x;
            else if (a != null && x.t() - a.t() >= 0.1) return Math.hypot(x.x() - a.x(), x.y() - a.y()) / (x.t() - a.t());
        }
        return Double.NaN;
    }

    /** Slope of ln(speed) over time, speeds from differences 0.1 s apart, while above 0.1 m/s. */
    static double fit(List<Sample> run) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        int n = 0;
        for (int i = 0; i < run.size(); i++) {
            Sample a = run.get(i);
            Sample b = null;
            for (int j = i + 1; j < run.size(); j++) if (run.get(j).t() - a.t() >= 0.1) { b = run.get(j); break; }
            if (b == null) break;
            double v = Math.hypot(b.x() - a.x(), b.y() - a.y()) / (b.t() - a.t());
            if (v < 0.1) break;
            double t = (a.t() + b.t()) / 2, y = Math.log(v);
            sx += t; sy += y; sxx += t * t; sxy += t * y; n++;
        }
        if (n < 3) return Double.NaN;
        return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
    }
}

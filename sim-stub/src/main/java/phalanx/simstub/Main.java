package phalanx.simstub;

import phalanx.comm.recording.Recordings;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Command line: {@code sim-stub <recording> [--port P] [--paced] [--log FILE]}. The recording is a
 * path prefix ({@code ../shared/recordings/S1}) or a perceptor file. Replays to one player, then
 * prints what it received and exits: 0 when the player answered every line, 1 otherwise, 2 on a
 * usage error.
 */
public final class Main {
    private static final String USAGE = "usage: scripts/phalanx replay <recording> [--port P] [--paced] [--log FILE]\n"
            + "  <recording>  path prefix such as ../shared/recordings/S1, or a *_perceptors.txt file\n"
            + "  --port P     port to listen on, 127.0.0.1 (default 3100)\n"
            + "  --paced      send a line every 20 ms instead of waiting for each reply\n"
            + "  --log FILE   write every received message to FILE, one per line (default: sim-stub-received.txt)";

    private Main() {}

    public static void main(String[] args) throws InterruptedException {
        System.exit(run(args));
    }

    static int run(String[] args) throws InterruptedException {
        Path recording = null;
        int port = 3100;
        boolean paced = false;
        Path log = Paths.get("sim-stub-received.txt");
        try {
            for (int i = 0; i < args.length; i++) {
                switch (args[i]) {
                    case "--port" -> port = Integer.parseInt(value(args, ++i, "--port"));
                    case "--paced" -> paced = true;
                    case "--log" -> log = Paths.get(value(args, ++i, "--log"));
                    case "-h", "--help" -> {
                        System.out.println(USAGE);
                        return 0;
                    }
                    default -> {
                        if (args[i].startsWith("-")) throw new IllegalArgumentException("unknown option " + args[i]);
                        if (recording != null) throw new IllegalArgumentException("only one recording, got a second: " + args[i]);
                        recording = Paths.get(args[i]);
                    }
                }
            }
            if (recording == null) throw new IllegalArgumentException("no recording given");
            if (port < 0 || port > 65535) throw new IllegalArgumentException("--port must be 0-65535, got " + port);
        } catch (NumberFormatException e) {
            System.err.println("sim-stub: --port needs a number\n" + USAGE);
            return 2;
        } catch (IllegalArgumentException e) {
            System.err.println("sim-stub: " + e.getMessage() + "\n" + USAGE);
            return 2;
        }
        Path file = recording.toString().endsWith(".txt") ? recording : Recordings.perceptorFile(recording);
        List<String> lines;
        try {
            lines = Files.readAllLines(file, java.nio.charset.StandardCharsets.ISO_8859_1);
        } catch (IOException e) {
            System.err.println("sim-stub: cannot read " + file + ": " + e);
            return 2;
        }
        try (ReplayServer server = new ReplayServer(lines, port,
                ReplayServer.Options.defaults().withPaced(paced).withLog(log))) {
            System.out.println("sim-stub: replaying " + lines.size() + " messages of " + file + " on 127.0.0.1:" + server.port()
                    + (paced ? " every 20 ms" : " in lock-step") + "; waiting for a player");
            ReplayServer.Result r = server.start().await(1, TimeUnit.DAYS);
            System.out.println("sim-stub: sent " + r.linesSent() + " lines, received " + r.received().size()
                    + " messages (" + r.repliesWithoutSyn() + " without (syn)), log in " + log);
            if (r.error() != null) {
                System.out.println("sim-stub: " + r.error());
                return 1;
            }
            return r.handshakeOk() ? 0 : 1;
        } catch (IOException e) {
            System.err.println("sim-stub: cannot listen on 127.0.0.1:" + port + ": " + e.getMessage());
            return 2;
        }
    }

    private static String value(String[] args, int i, String flag) {
        if (i >= args.length) throw new IllegalArgumentException(flag + " needs a value");
        return args[i];
    }
}

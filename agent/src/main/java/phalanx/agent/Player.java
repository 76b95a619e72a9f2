package phalanx.agent;

import phalanx.comm.wire.ServerConnection;
import phalanx.comm.wire.WireException;

import java.io.IOException;
import java.nio.file.Files;
import java.util.logging.FileHandler;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;

/**
 * One player process. Exit status: 0 after a normal end, 1 when the connection is lost, 2 on a
 * usage error, 3 when no server answered within 30 s.
 */
public final class Player {
    private static final Logger LOG = Logger.getLogger(Player.class.getName());

    private Player() {}

    public static void main(String[] args) {
        System.exit(run(args));
    }

    static int run(String[] args) {
        PlayerOptions o;
        try {
            o = PlayerOptions.parse(args);
        } catch (IllegalArgumentException e) {
            if (e.getMessage().equals("help")) {
                System.out.println(PlayerOptions.USAGE);
                return 0;
            }
            System.err.println("phalanx-player: " + e.getMessage() + "\n" + PlayerOptions.USAGE);
            return 2;
        }
        if (o.logDir() != null && !openLog(o)) return 2;
        ServerConnection c;
        try {
            c = ServerConnection.connect(o.host(), o.port(), o.connectTimeoutMillis());
        } catch (WireException e) {
            System.err.println("phalanx-player " + o.unum() + ": " + e.getMessage()
                    + " (is rcssserver3d running? see README)");
            return 3;
        }
        try (c) {
            LOG.info("connected to " + o.host() + ":" + o.port() + " as " + o.team() + " " + o.unum() + ", type " + o.robotType());
            ThinkLoop.Outcome out = new ThinkLoop(c, o, new StandAndBeam(o.unum(), o.players())).run();
            System.err.println("phalanx-player " + o.unum() + ": " + out.reason() + " after " + out.cycles() + " cycles ("
                    + out.malformed() + " malformed messages skipped)");
            return 1;
        }
    }

    private static boolean openLog(PlayerOptions o) {
        try {
            Files.createDirectories(o.logDir());
            FileHandler h = new FileHandler(o.logDir().resolve("player-" + o.team() + "-" + o.unum() + ".log").toString());
            h.setFormatter(new SimpleFormatter());
            Logger.getLogger("phalanx").addHandler(h);
            return true;
        } catch (IOException | SecurityException e) {
            System.err.println("phalanx-player: cannot write a log in " + o.logDir() + ": " + e.getMessage());
            return false;
        }
    }
}

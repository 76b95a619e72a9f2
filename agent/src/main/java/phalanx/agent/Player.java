package phalanx.agent;

import phalanx.agent.act.Body;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.action.FieldPlayerBehaviour;
import phalanx.agent.goalkeeper.GoalkeeperBehaviour;
import phalanx.agent.mj.MjPlayer;
import phalanx.agent.roboviz.RoboViz;
import phalanx.agent.team.TeamChannel;
import phalanx.agent.team.RoundPlanner;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.TeamKey;
import phalanx.comm.wire.ServerConnection;
import phalanx.comm.wire.WireException;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.Coordinator;
import phalanx.localization.belief.BeliefStore;
import phalanx.motion.MotionFileException;
import phalanx.motion.MotionLibrary;
import phalanx.motion.control.MotionController;

import java.io.IOException;
import java.nio.file.Files;
import java.util.logging.FileHandler;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;

/**
 * One player process. Exit status: 0 when the game ended (GameOver), 1 when the connection was
 * lost, 2 on a usage error or a bad motion file, 3 when no server answered in time.
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
        if (o.mj()) return MjPlayer.run(o);
        PlayerParts parts;
        try {
            parts = parts(o);
        } catch (MotionFileException e) {
            System.err.println("phalanx-player: bad motion file: " + e.getMessage());
            return 2;
        } catch (IOException | IllegalArgumentException e) {
            System.err.println("phalanx-player: cannot start: " + e.getMessage());
            return 2;
        }
        // Everything is built before connecting, so the scene goes out right after the connection
        // opens (an agent-sync server has stalled on a late scene: docs/protocol.md).
        PlayerRuntime runtime = new PlayerRuntime(o, parts);
        ServerConnection c;
        try {
            c = ServerConnection.connect(o.host(), o.port(), o.connectTimeoutMillis(), ThinkLoop.hello(o));
        } catch (WireException e) {
            System.err.println("phalanx-player " + o.unum() + ": " + e.getMessage() + " (is rcssserver3d running? see README)");
            return 3;
        }
        try (c) {
            LOG.info("connected to " + o.host() + ":" + o.port() + " as " + o.team() + " " + o.unum() + ", type " + o.robotType());
            ThinkLoop.Outcome out = new ThinkLoop(c, o, runtime).run();
            String msg = "phalanx-player " + o.unum() + ": " + out.reason() + " after " + out.cycles() + " cycles ("
                    + out.malformed() + " malformed messages skipped)";
            LOG.info(msg);
            System.err.println(msg);
            return out.gameOver() ? 0 : 1;
        }
    }

    /** Everything the player is made of; a bad motion file or RoboViz address fails here, at start. */
    static PlayerParts parts(PlayerOptions o) throws MotionFileException, IOException {
        PlayerConfig config = PlayerConfig.of(o);
        if (!Files.isDirectory(o.motions())) {
            throw new IOException("no motion folder at " + o.motions().toAbsolutePath() + " (use --motions DIR)");
        }
        MotionLibrary library = MotionLibrary.load(o.motions(), o.robotType());
        BeliefStore beliefs = new BeliefStore(config.field(), config.localization(), config.body(), o.team(), null, o.unum());
        RoboViz draw = o.roboviz() == null ? RoboViz.OFF : RoboViz.to(o.roboviz());
        TeamKey key = teamKey(o.team());
        Body body = new Body(new MotionController(library, config.motion()), config.walk(), config.motion(), o.robotType());
        return new PlayerParts(config, beliefs, body, draw, (unum, self) -> {
            PlayerParts.Role role = role(o, config, beliefs, key, unum, self);
            // thesis 6.3's "empty" player: on the team channel as usual, but no motion and no head tracking
            return o.still() ? new PlayerParts.Role(role.channel(), (s, c) -> Decision.of(Move.STAND, HeadTarget.STRAIGHT)) : role;
        });
    }

    private static PlayerParts.Role role(PlayerOptions o, PlayerConfig config, BeliefStore beliefs, TeamKey key,
                                         int unum, PlayerParts self) {
        ChannelConfig channel = config.channel();
        if (unum == channel.coordinator()) {
            GoalkeeperBrain keeper = new GoalkeeperBrain(new GoalkeeperBehaviour(config.agent()));
            Coordinator coordinator = new Coordinator(config.coordination(), new DynamicProgrammingSupportMapper());
            RoundPlanner procedure = new RoundPlanner(coordinator, config.field(), unum, beliefs::belief,
                    self::playMode, keeper::hasBall);
            return new PlayerParts.Role(TeamChannel.coordinator(channel, key, o.team(), procedure), keeper);
        }
        return new PlayerParts.Role(TeamChannel.fieldPlayer(channel, key, o.team(), unum),
                new FieldBrain(new FieldPlayerBehaviour(config.agent(), unum), unum, o.players(), config.coordination()));
    }

    /**
     * The per-match key start.sh passes in PHALANX_TEAM_KEY. Without one the player still plays, with a
     * key derived from the team name (logged: opponents who guess it could forge our messages).
     */
    public static TeamKey teamKey(String team) {
        try {
            return TeamKey.fromEnvironment(System.getenv());
        } catch (IllegalArgumentException e) {
            LOG.warning(e.getMessage() + "; using a key derived from the team name instead");
            return TeamKey.fromSecret("phalanx-team-key-" + team);
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

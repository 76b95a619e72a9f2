package phalanx.agent;

import phalanx.motion.MotionConfig;

import java.nio.file.Path;
import java.nio.file.Paths;

/** The player's command line (issue 8). {@link #parse} names the flag at fault. */
public record PlayerOptions(String host, int port, String team, int unum, int players, int robotType,
                            Path logDir, long connectTimeoutMillis, Path motions, String roboviz, boolean still,
                            int dribbleWithin, boolean mj, boolean thesisApproach, boolean kickOffKick, int standBeforeMillis, int standAfterMillis) {

    public static final String USAGE = """
            usage: phalanx-player [--host H] [--port P] [--team NAME] [--unum N] [--players 9|11] [--type T] [--log-dir DIR]
              --host H       server address (default 127.0.0.1)
              --port P       agent port (default 3100)
              --team NAME    team name, printable ASCII without spaces or parentheses (default Phalanx)
              --unum N       uniform number 1-11 (default 0: the server chooses)
              --players N    team size, 9 (server 0.6.5) or 11 (default 11)
              --type T       heterogeneous Nao type 0-4 (default 0)
              --log-dir DIR  directory for this player's log (default: no log file, stderr only)
              --connect-timeout S  seconds to keep retrying while no server listens (default 30)
              --motions DIR  the motion files (default: motions/ in the working directory)
              --roboviz H[:P]  draw beliefs into RoboViz at H (port 32769 by default); off by default
              --behaviour B  play (default) or still: beam, stand and do nothing else (the "empty"
                             goalkeeper of the thesis's test 6.3)
              --dribble-within M  in PlayOn, dribble toward the goal instead of kicking while the ball is
                             nearer than M metres to it (default 8, from games: docs/matches.md session 10;
                             0: always kick, the thesis; 100: always dribble)
              --approach A   omni (default: the omnidirectional walk to the spot behind the ball, facing the goal;
                             AgentConfig.Approach) or thesis (4.6.2: Walk To Ball, then the align orbit)
              --kick-off K   kick (default: On Ball as in any mode; on an empty field the taker's second touch
                             is a foul) or tap (player 10 taps the ball and player 9 plays it; AgentConfig.KickOff.TAP)
              --stand-before MS  before a kick, once the walk has stopped, stand MS milliseconds (0-2000;
                             default MotionConfig.standBeforeSeconds)
              --stand-after MS   after a kick, get-up or dive, stand MS milliseconds, easing into the walk's crouch,
                             before stepping (0-2000; default MotionConfig.standAfterSeconds)
              --server S     simspark (default: rcssserver3d, a Nao) or mj (rcssservermj, a Booster T1; 7 players,
                             --unum 1-7; docs/rcssservermj.md)""";

    public static PlayerOptions defaults() {
        return new PlayerOptions("127.0.0.1", 3100, "Phalanx", 0, 11, 0, null, 30_000, Paths.get("motions"), null, false, 8, false, false, false,
                millis(MotionConfig.DEFAULT.standBeforeSeconds()), millis(MotionConfig.DEFAULT.standAfterSeconds()));
    }

    /** Parses flags; throws IllegalArgumentException whose message names the bad flag and value. */
    public static PlayerOptions parse(String... args) {
        PlayerOptions o = defaults();
        String host = o.host, team = o.team;
        int port = o.port, unum = o.unum, players = o.players, type = o.robotType;
        Path logDir = null;
        long connectMillis = o.connectTimeoutMillis;
        Path motions = o.motions;
        String roboviz = null;
        boolean still = false;
        int dribbleWithin = o.dribbleWithin;
        boolean mj = false, thesisApproach = false, kickOffKick = true;
        int standBeforeMillis = o.standBeforeMillis, standAfterMillis = o.standAfterMillis;
        for (int i = 0; i < args.length; i++) {
            String flag = args[i];
            if (flag.equals("-h") || flag.equals("--help")) throw new IllegalArgumentException("help");
            if (!flag.startsWith("--")) throw new IllegalArgumentException("unexpected argument '" + flag + "'");
            if (i + 1 >= args.length) throw new IllegalArgumentException(flag + " needs a value");
            String v = args[++i];
            switch (flag) {
                case "--host" -> host = v;
                case "--port" -> port = intIn(flag, v, 1, 65535);
                case "--team" -> team = teamName(v);
                case "--unum" -> unum = intIn(flag, v, 0, 11);
                case "--players" -> {
                    players = intIn(flag, v, 9, 11);
                    if (players == 10) throw new IllegalArgumentException("--players must be 9 or 11, got 10");
                }
                case "--type" -> type = intIn(flag, v, 0, 4);
                case "--log-dir" -> logDir = Paths.get(v);
                case "--connect-timeout" -> connectMillis = intIn(flag, v, 0, 3600) * 1000L;
                case "--motions" -> motions = Paths.get(v);
                case "--roboviz" -> roboviz = v;
                case "--behaviour" -> {
                    if (!v.equals("play") && !v.equals("still")) throw new IllegalArgumentException("--behaviour must be play or still, got '" + v + "'");
                    still = v.equals("still");
                }
                case "--dribble-within" -> dribbleWithin = intIn(flag, v, 0, 100);
                case "--approach" -> {
                    if (!v.equals("omni") && !v.equals("thesis")) throw new IllegalArgumentException("--approach must be omni or thesis, got '" + v + "'");
                    thesisApproach = v.equals("thesis");
                }
                case "--kick-off" -> {
                    if (!v.equals("tap") && !v.equals("kick")) throw new IllegalArgumentException("--kick-off must be tap or kick, got '" + v + "'");
                    kickOffKick = v.equals("kick");
                }
                case "--stand-before" -> standBeforeMillis = intIn(flag, v, 0, 2000);
                case "--stand-after" -> standAfterMillis = intIn(flag, v, 0, 2000);
                case "--server" -> {
                    if (!v.equals("simspark") && !v.equals("mj")) throw new IllegalArgumentException("--server must be simspark or mj, got '" + v + "'");
                    mj = v.equals("mj");
                }
                default -> throw new IllegalArgumentException("unknown flag " + flag);
            }
        }
        if (unum > players) throw new IllegalArgumentException("--unum " + unum + " is more than --players " + players);
        return new PlayerOptions(host, port, team, unum, players, type, logDir, connectMillis, motions, roboviz, still, dribbleWithin, mj, thesisApproach, kickOffKick, standBeforeMillis, standAfterMillis);
    }

    private static int millis(double seconds) { return (int) Math.round(seconds * 1000); }

    private static int intIn(String flag, String v, int min, int max) {
        int n;
        try {
            n = Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(flag + " needs a whole number, got '" + v + "'");
        }
        if (n < min || n > max) throw new IllegalArgumentException(flag + " must be " + min + "-" + max + ", got " + n);
        return n;
    }

    private static String teamName(String v) {
        if (v.isEmpty() || v.length() > 16 || !v.chars().allMatch(c -> c > 0x20 && c < 0x7f && c != '(' && c != ')')) {
            throw new IllegalArgumentException("--team must be 1-16 printable characters without spaces or parentheses, got '" + v + "'");
        }
        return v;
    }
}

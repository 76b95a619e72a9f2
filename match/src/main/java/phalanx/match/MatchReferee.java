package phalanx.match;

import java.nio.file.Path;
import java.util.Set;

/**
 * scripts/phalanx match: one match between two teams given as start commands, on a server of its own.
 * Exit status 0 when the game reached GameOver, 1 when it did not (the JSON says why), 2 on a usage error,
 * 3 when no game was played because this machine's server never came up (no server, ports taken, no
 * monitor port: the JSON says why); a tournament's parallel job retries a 3 on another host.
 */
public final class MatchReferee {
    static final String USAGE = """
            usage: scripts/phalanx match --left NAME='COMMAND' --right NAME='COMMAND' [options]
              COMMAND starts a team; {host} {port} {dir} are replaced by 127.0.0.1, the agent port and a log
              folder for that team, e.g. --left "Phalanx=scripts/start.sh {host} {port} Phalanx --log-dir {dir}".
              --left starts first and so normally plays on the left.
              --dir DIR            where the server, team and match logs go (default /tmp/phalanx-matches/<time>-A-vs-B)
              --out FILE           the result JSON (default DIR/result.json)
              --server S           simspark (default: rcssserver3d) or mj (rcssservermj: one server run per half,
                                   agent-sync without real time, --players 7 and --half-time up to 300 by default;
                                   found as $PHALANX_RCSSSERVERMJ, .venv/bin/rcssservermj or on PATH)
            """ + MatchOptions.HELP;

    private MatchReferee() { }

    public static void main(String[] argv) {
        MatchRunner runner;
        try {
            Args a = MatchOptions.parse(argv, USAGE, "match", Set.of("left", "right", "dir", "out", "server"), Set.of());
            String server = a.get("server", "simspark");
            if (!server.equals("simspark") && !server.equals("mj")) {
                throw new IllegalArgumentException("match: --server must be simspark or mj, got '" + server + "'");
            }
            if (a.get("left", null) == null || a.get("right", null) == null) {
                throw new IllegalArgumentException("match: both --left and --right are needed");
            }
            TeamCommand left = TeamCommand.parse(a.get("left", null));
            TeamCommand right = TeamCommand.parse(a.get("right", null));
            Path dir = Path.of(a.get("dir", "/tmp/phalanx-matches/" + MatchOptions.stamp() + "-" + left.label() + "-vs-" + right.label()));
            Path out = Path.of(a.get("out", dir.resolve("result.json").toString()));
            if (server.equals("mj")) {
                playMj(a, left, right, dir, out);
                return;
            }
            runner = new MatchRunner(MatchOptions.config(a, left, right, dir, out), System.out);
        } catch (IllegalArgumentException | IllegalStateException e) {
            System.err.println(e.getMessage());
            System.err.println("(scripts/phalanx match --help for the options)");
            System.exit(2);
            return;
        }
        MatchRunner r = runner;
        Thread hook = new Thread(() -> r.abort("interrupted (Ctrl-C or SIGTERM)"), "match-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        MatchResult result = r.run();
        System.exit(result != null && result.completed() ? 0 : r.serverRan() ? 1 : 3);
    }

    private static void playMj(Args a, TeamCommand left, TeamCommand right, Path dir, Path out) {
        Path exe = MjServerProcess.find(System.getenv(), Path.of(System.getProperty("user.dir"))).orElseThrow(() ->
                new IllegalArgumentException("match: no rcssservermj ($PHALANX_RCSSSERVERMJ, .venv/bin, PATH): run scripts/setup.sh"));
        int agent = a.integer("agent-port", 0, 0, 65535);
        if (agent == 0) agent = MatchOptions.freeAgentPort(a, 3700);
        MjMatch m = new MjMatch(new MjMatch.Config(exe, left, right, agent, a.integer("monitor-port", agent + 100, 1, 65535),
                a.number("half-time", MjMatch.Config.RULE_HALF, 1, MjMatch.Config.RULE_HALF), a.integer("halves", 2, 1, 2),
                a.integer("players", 7, 1, 7), a.number("connect-timeout", 120, 1, 3600), dir, out), System.out);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> m.abort("interrupted (Ctrl-C or SIGTERM)"), "match-stop"));
        MatchResult result = m.run();
        System.exit(result != null && result.completed() ? 0 : 1);
    }
}

package phalanx.match;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Set;

/** The server and timing options shared by scripts/phalanx match, tournament and keeper-test. */
final class MatchOptions {
    static final Set<String> VALUED = Set.of("agent-port", "monitor-port", "half-time", "halves", "players",
            "connect-timeout", "connect-quiet", "settle", "stall", "max-wall", "port-slot");
    static final Set<String> FLAGS = Set.of("sync", "fast", "allow-empty");
    static final String HELP = """
              --sync               agent-sync mode: the server waits for every player's (syn) each cycle
                                   (no lost cycles on a slow machine; still never faster than real time)
              --fast               agent-sync mode without real time: as fast as the slowest player
              --half-time S        game seconds per half (default 300, the server's)
              --halves 1|2         (default 2)
              --players N          players per team (default 11)
              --agent-port P       (default: a free P from 3500 on); --monitor-port M (default P+100)
              --port-slot S        choose P only from 3500+200(S-1) to 3500+200(S-1)+99 (monitor P+100): games
                                   in different slots never pick the same ports (the tournament's parallel jobs)
              --connect-timeout S  per team, to get its players on the field (default 120)
              --connect-quiet S    a team is complete when no player joined for S seconds (default 15)
              --settle S           between the last player and each kick-off (default 3)
              --stall S            give up when the monitor is silent this long (default 60)
              --max-wall S         give up after this many wall seconds (default 6 x game length + start-up)
              --allow-empty        play even if a team puts no player on the field (thesis 6.3's "no goalkeeper")""";

    private MatchOptions() { }

    /**
     * A main's command line: the match options plus the program's own; no argument prints the usage
     * and exits 2, -h/--help prints it and exits 0.
     */
    static Args parse(String[] argv, String usage, String program, Set<String> valued, Set<String> flags) {
        if (argv.length == 0 || argv[0].equals("-h") || argv[0].equals("--help")) {
            System.out.println(usage);
            System.exit(argv.length == 0 ? 2 : 0);
        }
        Set<String> v = new java.util.HashSet<>(VALUED);
        v.addAll(valued);
        Set<String> f = new java.util.HashSet<>(FLAGS);
        f.addAll(flags);
        return new Args(argv, v, f, program);
    }

    /** Server settings; the ports are chosen now (free ones from 3500 on unless given). */
    static ServerProcess.Settings server(Args a) {
        boolean fast = a.flag("fast");
        int agent = a.integer("agent-port", 0, 0, 65535);
        if (agent == 0) agent = freeAgentPort(a, 3500);
        int monitor = a.integer("monitor-port", agent + 100, 1, 65535);
        if (monitor == agent) throw new IllegalArgumentException("--monitor-port must differ from --agent-port");
        return new ServerProcess.Settings(agent, monitor, fast || a.flag("sync"), !fast,
                a.number("half-time", 300, 1, 3600), a.integer("halves", 2, 1, 2));
    }

    /** The highest --port-slot: its range ends below 65535. */
    static final int MAX_PORT_SLOT = 300;

    /** The first agent port of a port slot (1 ...): slot S owns [3500+200(S-1), 3500+200S), agent ports the first 100. */
    static int slotBase(int slot) { return 3500 + 200 * (slot - 1); }

    /** A free agent port (its monitor port P+100 free too): from {@code from} on, or within --port-slot's range. */
    static int freeAgentPort(Args a, int from) {
        int slot = a.integer("port-slot", 0, 1, MAX_PORT_SLOT);
        return slot == 0 ? ServerProcess.freePortPair(from) : ServerProcess.freePortPair(slotBase(slot), 100);
    }

    static MatchConfig config(Args a, TeamCommand first, TeamCommand second, Path dir, Path out) {
        ServerProcess.Settings s = server(a);
        double connect = a.number("connect-timeout", 120, 1, 3600);
        return new MatchConfig(first, second, s, a.integer("players", 11, 1, 11), connect,
                a.number("connect-quiet", 15, 1, 600), a.number("settle", 3, 0, 600), a.number("stall", 60, 5, 3600),
                a.number("max-wall", MatchConfig.defaultMaxWall(s, connect), 10, 1e6), dir, out,
                Path.of(System.getProperty("user.dir")), a.flag("allow-empty"));
    }

    static String stamp() { return LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")); }
}

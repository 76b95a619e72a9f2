package phalanx.bench.walk;

import phalanx.motion.walk.WalkConfig;
import phalanx.motion.walk.MixedCommands;
import phalanx.match.Flags;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Command line of scripts/phalanx bench walk. Every bad flag gets a message naming it.
 *
 * @param scenarios   which trials: forward10, forward60, turn, side, mixed (in the order listed; mixed
 *                    only when named)
 * @param set         config fields to override, {@code name=value}
 * @param search      fields to tune by coordinate descent, with their first step: {@code name:step}
 * @param rounds      coordinate-descent rounds (each halves the steps)
 * @param searchSeconds length of one forward trial of the search
 * @param starts      forward trials are repeated from this many start points 0.7 m apart (the
 *                    server is deterministic: only another start gives another outcome); mixed
 *                    trials run this many sequences, seeds {@code seed}, {@code seed + 1}, ...
 * @param seed        first seed of the mixed scenario's request sequence ({@link MixedCommands})
 * @param mixedSeconds length of one mixed trial
 * @param score       instead of trials or a search: the search's score of the config (one type), printed
 *                    as {@code SCORE s} (the CMA-ES walk search's evaluator)
 */
public record WalkTrialOptions(String host, int port, int monitorPort, List<Integer> types, List<String> scenarios,
                               Map<String, Double> set, Map<String, Double> search, int rounds, double searchSeconds,
                               double turnSeconds, double sideSeconds, int starts, long seed, double mixedSeconds,
                               boolean score) {

    public static final List<String> SCENARIOS = List.of("forward10", "forward60", "turn", "side", "mixed");
    /** What runs without --scenarios (mixed is asked for by name: a minute per start and type). */
    public static final List<String> DEFAULT_SCENARIOS = List.of("forward10", "forward60", "turn", "side");
    public static final String USAGE = """
            usage: scripts/phalanx bench walk %s [--type 0,2,4] \
            [--scenarios forward10,forward60,turn,side,mixed] [--set field=value,...] [--search field:step,...] \
            [--rounds 3] [--search-seconds 15] [--turn-seconds 10] [--side-seconds 10] [--starts 1] \
            [--seed 1] [--mixed-seconds 60] [--score]""".formatted(Flags.SERVER_USAGE);

    public static WalkTrialOptions parse(String... args) {
        Flags.Server server = new Flags.Server();
        int rounds = 3, starts = 1;
        long seed = 1;
        double searchSeconds = 15, turnSeconds = 10, sideSeconds = 10, mixedSeconds = 60;
        List<Integer> types = List.of(0, 2, 4);
        List<String> scenarios = DEFAULT_SCENARIOS;
        Map<String, Double> set = new LinkedHashMap<>(), search = new LinkedHashMap<>();
        boolean score = false;
        for (String[] p : Flags.pairs(args, USAGE, Set.of("--score"))) {
            String flag = p[0], v = p[1];
            if (server.read(flag, v)) continue;
            switch (flag) {
                case "--rounds" -> rounds = (int) Flags.number(flag, v, 1, 20, true);
                case "--starts" -> starts = (int) Flags.number(flag, v, 1, 10, true);
                case "--search-seconds" -> searchSeconds = Flags.number(flag, v, 2, 600, false);
                case "--turn-seconds" -> turnSeconds = Flags.number(flag, v, 1, 600, false);
                case "--seed" -> seed = (long) Flags.number(flag, v, 0, 1e9, true);
                case "--mixed-seconds" -> mixedSeconds = Flags.number(flag, v, 1, 3600, false);
                case "--side-seconds" -> sideSeconds = Flags.number(flag, v, 1, 600, false);
                case "--type" -> types = Flags.types(flag, v);
                case "--scenarios" -> {
                    List<String> s = new ArrayList<>();
                    for (String name : v.split(",")) {
                        if (!SCENARIOS.contains(name.strip())) throw new IllegalArgumentException("--scenarios: unknown scenario '" + name + "' (know " + SCENARIOS + ")");
                        s.add(name.strip());
                    }
                    scenarios = List.copyOf(s);
                }
                case "--set" -> pairs(flag, v, '=', set, false);
                case "--search" -> search.putAll(steps(flag, v));
                case "--score" -> score = true;
                default -> throw Flags.unknown(flag, USAGE);
            }
        }
        if (score && !search.isEmpty()) throw new IllegalArgumentException("--score and --search exclude each other");
        if (score && types.size() != 1) throw new IllegalArgumentException("--score scores one robot type: give --type with one type, got " + types);
        return new WalkTrialOptions(server.host, server.port, server.monitorPort, types, scenarios, Map.copyOf(set), java.util.Collections.unmodifiableMap(search),
                rounds, searchSeconds, turnSeconds, sideSeconds, starts, seed, mixedSeconds, score);
    }

    /** The default walk config with the {@code --set} overrides; a bad field or value gets its message. */
    public WalkConfig config() { return config(0); }

    /** The tuned config of a robot type with the {@code --set} overrides. */
    public WalkConfig config(int type) {
        WalkConfig c = WalkConfig.forType(type);
        for (Map.Entry<String, Double> e : set.entrySet()) c = c.with(e.getKey(), e.getValue());
        return c;
    }

    /** {@code field:step,...} as {@code --search} takes it (the CMA-ES search's FIELDS too), in order; steps > 0. */
    static Map<String, Double> steps(String flag, String v) {
        Map<String, Double> steps = new LinkedHashMap<>();
        pairs(flag, v, ':', steps, true);
        return steps;
    }

    private static void pairs(String flag, String v, char sep, Map<String, Double> into, boolean positive) {
        for (String p : v.split(",")) {
            int k = p.indexOf(sep);
            if (k <= 0 || k == p.length() - 1) throw new IllegalArgumentException(flag + " needs field" + sep + "number pairs, got '" + p + "'");
            String field = p.substring(0, k).strip();
            if (!WalkConfig.FIELDS.contains(field)) throw new IllegalArgumentException(flag + ": walk config has no field '" + field + "'");
            double d = Flags.number(flag + " " + field, p.substring(k + 1).strip(), positive ? 1e-9 : -1e9, 1e9, false);
            into.put(field, d);
        }
    }

}

package phalanx.bench.motion;

import phalanx.match.Flags;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Command line of scripts/motion-bench. Every bad flag gets a message naming it.
 *
 * @param types robot types to measure (the server needs at least three types in a team of eleven,
 *              DESIGN.md, so the team fields 0, 1 and 2 at least)
 * @param kicks       kick motions the kick trial plays; a name ending in {@code _left} kicks with the
 *                    left foot and gets the ball on the left
 * @param ballAhead   kick trial: the ball's centre this far ahead of the torso centre (m)
 * @param ballSide    kick trial: and this far to the side of the kicking foot (m)
 * @param ballJitter  kick trial: each trial moves the ball by up to this much ahead/back and to either side
 *                    (uniform, seeded), as the agent's Prepare For Kick leaves it within its tolerance (m)
 * @param diveOffset  dive trial: the shot passes the keeper's centre this far to the diving side (m)
 * @param shotSeconds dive trial: the shot crosses the keeper's line this long after the dive request (s)
 * @param getupWalkSeconds after a get-up that stood, walk forward at full speed this long (0: no walk)
 * @param lying           get-up trials to run in each trial round: front, back, side (left/right in turn),
 *                        oblique (the four diagonals in turn)
 */
public record BenchOptions(String host, int port, int monitorPort, List<Integer> types, int trials,
                           double walkSeconds, double turnSeconds, Path motions, String only, boolean trace,
                           List<String> kicks, double ballAhead, double ballSide, double ballJitter, double diveOffset, double shotSeconds,
                           double getupWalkSeconds, List<String> lying) {

    public static final String USAGE = """
            usage: scripts/phalanx bench motion %s [--type 0,1,2] [--trials 3] [--walk-seconds 10] \
            [--turn-seconds 5] [--motions motions] [--only walk|turn|kick|getup|dive] [--trace] [--kicks kick,strong_kick] \
            [--ball-ahead 0.17] [--ball-side 0.055] [--ball-jitter 0] [--dive-offset 0.6] [--shot-seconds 0.8] \
            [--getup-walk 2] [--lying front,back,side,oblique]""".formatted(Flags.SERVER_USAGE);

    public static BenchOptions parse(String... args) {
        Flags.Server server = new Flags.Server();
        int trials = 3;
        double walk = 10, turn = 5, getupWalk = 2;
        List<Integer> types = List.of(0, 1, 2);
        Path motions = Path.of("motions");
        String only = null;
        boolean trace = false;
        List<String> kicks = List.of("kick", "strong_kick");
        double ballAhead = 0.17, ballSide = 0.055, ballJitter = 0, diveOffset = 0.6, shotSeconds = 0.8;
        List<String> lying = List.of("front", "back", "side", "oblique");
        for (String[] p : Flags.pairs(args, USAGE, Set.of("--trace"))) {
            String flag = p[0], v = p[1];
            if (server.read(flag, v)) continue;
            switch (flag) {
                case "--trace" -> trace = true;
                case "--trials" -> trials = (int) Flags.number(flag, v, 1, 100, true);
                case "--walk-seconds" -> walk = Flags.number(flag, v, 1, 600, false);
                case "--turn-seconds" -> turn = Flags.number(flag, v, 1, 600, false);
                case "--motions" -> motions = Path.of(v);
                case "--getup-walk" -> getupWalk = Flags.number(flag, v, 0, 60, false);
                case "--lying" -> {
                    List<String> l = new ArrayList<>();
                    for (String s : v.split(",")) {
                        String w = s.strip();
                        if (!List.of("front", "back", "side", "oblique").contains(w)) throw new IllegalArgumentException("--lying takes front, back, side, oblique, got '" + w + "'");
                        if (!l.contains(w)) l.add(w);
                    }
                    lying = List.copyOf(l);
                }
                case "--only" -> {
                    if (!List.of("walk", "turn", "kick", "getup", "dive").contains(v)) throw new IllegalArgumentException("--only must be walk, turn, kick, getup or dive, got '" + v + "'");
                    only = v;
                }
                case "--kicks" -> {
                    List<String> k = new ArrayList<>();
                    for (String m : v.split(",")) if (!m.isBlank()) k.add(m.strip());
                    if (k.isEmpty()) throw new IllegalArgumentException("--kicks needs at least one motion name, got '" + v + "'");
                    kicks = List.copyOf(k);
                }
                case "--ball-ahead" -> ballAhead = Flags.number(flag, v, 0, 0.5, false);
                case "--ball-side" -> ballSide = Flags.number(flag, v, -0.2, 0.2, false);
                case "--ball-jitter" -> ballJitter = Flags.number(flag, v, 0, 0.05, false);
                case "--dive-offset" -> diveOffset = Flags.number(flag, v, 0, 2, false);
                case "--shot-seconds" -> shotSeconds = Flags.number(flag, v, 0.1, 3, false);
                case "--type" -> types = Flags.types(flag, v);
                default -> throw Flags.unknown(flag, USAGE);
            }
        }
        return new BenchOptions(server.host, server.port, server.monitorPort, types, trials, walk, turn, motions, only, trace,
                kicks, ballAhead, ballSide, ballJitter, diveOffset, shotSeconds, getupWalk, lying);
    }

    public boolean runs(String what) { return only == null || only.equals(what); }

}

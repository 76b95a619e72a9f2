package phalanx.motion.walk;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * A game-like sequence of walk requests for the {@code mixed} scenario of scripts/phalanx bench walk: what
 * the agent's Body asks of the walk while its players chase moving targets (agent Steer and Body):
 * full speed with a lean (turn up to half the turn limit), turns in place, slow approaches, side
 * steps, steps back, stops, and bursts of walk/turn alternation as Steer produces when the heading
 * error crosses its lean threshold. Seeded, so a run is repeatable. Values in, values out.
 */
public final class MixedCommands {
    /** Each request lasts this long (seconds): targets move every ~0.5 s in a game. */
    public static final double MIN_SECONDS = 0.3, MAX_SECONDS = 2.0;
    /** Alternation bursts: each walk or turn piece lasts this long. */
    static final double BURST_MIN = 0.3, BURST_MAX = 1.0;

    /** What a request stands for (the agent's Move behind it). */
    public enum Kind { FORWARD, TURN, SLOW, SIDE, BACK, STOP, STEER_WALK, STEER_TURN }

    /** One request held for {@code seconds}. */
    public record Segment(double seconds, WalkVelocity request, Kind kind) {
        @Override public String toString() {
            return String.format(java.util.Locale.ROOT, "%s(%.2f,%.2f,%.0f) %.2fs", kind.name().toLowerCase(java.util.Locale.ROOT),
                    request.forward(), request.left(), request.turnDeg(), seconds);
        }
    }

    private MixedCommands() {}

    /**
     * Requests for at least {@code totalSeconds}, scaled to the config's limits as Body scales Moves:
     * full forward = maxForward with a turn of up to ±maxTurnDeg/2 (Walk's lean), slow = 0.4 of it,
     * turn in place 1/3..1 of maxTurnDeg (Turn's gain 0.3..1.0 of 90 deg/s), side = ±maxLeft,
     * back = −0.5 maxBackward, stop = zero.
     */
    public static List<Segment> generate(long seed, double totalSeconds, WalkConfig c) {
        if (!(totalSeconds > 0) || !Double.isFinite(totalSeconds)) throw new IllegalArgumentException("mixed sequence length must be a positive number of seconds, got " + totalSeconds);
        SplittableRandom r = new SplittableRandom(seed);
        List<Segment> out = new ArrayList<>();
        double t = 0;
        while (t < totalSeconds) {
            int pick = r.nextInt(100);
            if (pick < 25) {          // Steer's alternation: walk with a lean, turn in place, walk ...
                int pieces = 2 + r.nextInt(5);
                int dir = r.nextBoolean() ? 1 : -1;
                for (int k = 0; k < pieces; k++) {
                    double s = r.nextDouble(BURST_MIN, BURST_MAX);
                    WalkVelocity v = k % 2 == 0
                            ? new WalkVelocity(c.maxForward(), 0, dir * r.nextDouble(0.5, 1.0) * 0.5 * c.maxTurnDeg())
                            : new WalkVelocity(0, 0, dir * r.nextDouble(0.3, 1.0) * c.maxTurnDeg());
                    out.add(new Segment(s, v, k % 2 == 0 ? Kind.STEER_WALK : Kind.STEER_TURN));
                    t += s;
                }
                continue;
            }
            double s = r.nextDouble(MIN_SECONDS, MAX_SECONDS);
            Segment seg;
            if (pick < 45) seg = new Segment(s, new WalkVelocity(c.maxForward(), 0, lean(r) * 0.5 * c.maxTurnDeg()), Kind.FORWARD);
            else if (pick < 62) seg = new Segment(s, new WalkVelocity(0, 0, sign(r) * r.nextDouble(1.0 / 3, 1.0) * c.maxTurnDeg()), Kind.TURN);
            else if (pick < 74) seg = new Segment(s, new WalkVelocity(0.4 * c.maxForward(), 0, lean(r) * 0.5 * c.maxTurnDeg()), Kind.SLOW);
            else if (pick < 84) seg = new Segment(s, new WalkVelocity(0, sign(r) * c.maxLeft(), 0), Kind.SIDE);
            else if (pick < 92) seg = new Segment(s, new WalkVelocity(-0.5 * c.maxBackward(), 0, 0), Kind.BACK);
            else seg = new Segment(s, WalkVelocity.ZERO, Kind.STOP);
            out.add(seg);
            t += s;
        }
        return List.copyOf(out);
    }

    /** A lean −1..1; a third of the time straight (lean 0), as when the target is dead ahead. */
    private static double lean(SplittableRandom r) { return r.nextInt(3) == 0 ? 0 : r.nextDouble(-1, 1); }

    private static int sign(SplittableRandom r) { return r.nextBoolean() ? 1 : -1; }
}

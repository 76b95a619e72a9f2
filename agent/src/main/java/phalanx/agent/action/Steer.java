package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;

/**
 * The two ways of changing heading (4.5.5, 4.6.2 Walk To Direction): a leaning walk for small
 * errors, a turn in place with a gain sized to the error for large ones. Every number that
 * reaches a Move is finite (the motion request refuses NaN).
 */
public final class Steer {
    private Steer() {}

    /** Turn in place toward a bearing (+ left), with the Turn Gain that turns about that much. */
    public static Move turn(double bearingDeg, AgentConfig.Walk w) {
        double a = Math.abs(bearingDeg);
        // Figure 4.10: gain 0.3 .. 1.0 turns 7 .. 40 degrees, roughly linearly.
        double g = w.gainMin() + (w.gainMax() - w.gainMin()) * (a - w.turnMinDeg()) / (w.turnMaxDeg() - w.turnMinDeg());
        return new Move.Turn(bearingDeg > 0, Facts.clamp(g, w.gainMin(), w.gainMax()));
    }

    /**
     * Walk To Direction's rule: below {@code leanBelowDeg} of heading error walk leaning into it
     * (full lean at the threshold), above it turn first.
     */
    public static Move toward(double errorDeg, boolean slow, AgentConfig.Walk w) {
        if (!Double.isFinite(errorDeg)) return Move.STAND;
        if (Math.abs(errorDeg) < w.leanBelowDeg()) {
            return new Move.Walk(Facts.clamp(errorDeg / w.leanBelowDeg(), -1, 1), slow);
        }
        return turn(errorDeg, w);
    }
}

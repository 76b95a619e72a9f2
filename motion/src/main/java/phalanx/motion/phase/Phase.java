package phalanx.motion.phase;

import phalanx.comm.perception.Joint;

import java.util.EnumMap;
import java.util.Map;

/**
 * One phase of an XML motion (4.5.1): joint targets in degrees for the listed joints, a duration,
 * the index of the next phase and of the finalize phase (-1 when absent), and, for walks, which leg
 * swings forward in it (used by Walk Leaning, 4.5.5).
 */
public final class Phase {
    /** Which leg swings forward in a walk phase; NONE for phases that are not steps. */
    public enum Swing { NONE, LEFT, RIGHT }

    private final String name;
    private final double[] targetsDeg; // NaN = joint not listed: it gets velocity 0 (4.5.2)
    private final int durationMs;
    private final int next;
    private final int finalizeTo;
    private final Swing swing;
    private final Check check;

    Phase(String name, double[] targetsDeg, int durationMs, int next, int finalizeTo, Swing swing) {
        this(name, targetsDeg, durationMs, next, finalizeTo, swing, null);
    }

    Phase(String name, double[] targetsDeg, int durationMs, int next, int finalizeTo, Swing swing, Check check) {
        this.name = name;
        this.targetsDeg = targetsDeg;
        this.durationMs = durationMs;
        this.next = next;
        this.finalizeTo = finalizeTo;
        this.swing = swing;
        this.check = check;
    }

    public String name() { return name; }
    public int durationMs() { return durationMs; }
    /** Index of the next phase in {@link PhaseMotion#phases()}, or -1 when the motion ends here. */
    public int next() { return next; }
    /** Index of the phase to go to when finalizing from here, or -1. */
    public int finalizeTo() { return finalizeTo; }
    public Swing swing() { return swing; }
    /** The torso check tested when this phase ends, or null. */
    public Check check() { return check; }
    public boolean lists(Joint j) { return !Double.isNaN(targetsDeg[j.ordinal()]); }
    /** Target in degrees, NaN for a joint this phase does not list. */
    public double targetDeg(Joint j) { return targetsDeg[j.ordinal()]; }

    public Map<Joint, Double> targets() {
        Map<Joint, Double> m = new EnumMap<>(Joint.class);
        for (Joint j : Joint.values()) if (lists(j)) m.put(j, targetDeg(j));
        return m;
    }

    @Override public String toString() {
        return "Phase[" + name + ", " + durationMs + " ms, " + targets() + ", next=" + next + ", finalize=" + finalizeTo + (check == null ? "" : ", " + check) + "]";
    }
}

package phalanx.motion.phase;

import phalanx.comm.perception.Vector3;

/**
 * A phase's torso check, tested when the phase ends (closed-loop get-ups): the share of "up" along
 * one torso axis, read from the accelerometer at rest, must lie in [min, max]; if not, the motion
 * goes to the phase {@code elsePhase} of the same file (at most once per play, so it cannot loop
 * forever) or switches to the motion {@code switchTo}. Without a usable reading the check passes,
 * and the motion plays on as an open-loop one.
 */
public record Check(Axis axis, double min, double max, int elsePhase, String switchTo, int line) {
    /** The torso axis whose share of world "up" is tested (server torso frame: x right, y forward, z up). */
    public enum Axis {
        RIGHT, FORWARD, UP;

        /** The component of the unit "up" vector along this axis; NaN without a reading. */
        public double share(Vector3 acc) {
            if (acc == null || !acc.isFinite()) return Double.NaN;
            double n = acc.norm();
            if (n < 1.0) return Double.NaN;               // no gravity in the reading (first messages)
            return switch (this) { case RIGHT -> acc.x() / n; case FORWARD -> acc.y() / n; case UP -> acc.z() / n; };
        }
    }

    /** True when the reading is within [min, max], or when there is no usable reading. */
    public boolean passes(Vector3 acc) {
        double s = axis.share(acc);
        return Double.isNaN(s) || (s >= min && s <= max);
    }
}

package phalanx.motion.control;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Joint;

import java.util.Arrays;

/**
 * One cycle's hinge commands in rad/s (the server's unit, recordings README). A joint the robot
 * does not have (no reading, e.g. toes on types 0-3) has no command and is not sent.
 */
public final class JointVelocities {
    private static final Joint[] JOINTS = Joint.values();
    private final double[] radPerSecond;

    JointVelocities(double[] radPerSecond) { this.radPerSecond = radPerSecond; }

    /** Commands in rad/s by {@link Joint#ordinal()}, NaN for none (used by the walk, phalanx.motion.walk). */
    public static JointVelocities of(double[] radPerSecond) {
        if (radPerSecond.length != Joint.COUNT) throw new IllegalArgumentException("need " + Joint.COUNT + " commands, got " + radPerSecond.length);
        return new JointVelocities(radPerSecond.clone());
    }

    public boolean has(Joint j) { return !Double.isNaN(radPerSecond[j.ordinal()]); }

    /** The command in rad/s, NaN for a joint that gets none. */
    public double radPerSecond(Joint j) { return radPerSecond[j.ordinal()]; }

    /**
     * A copy with one joint's command replaced (clamped by the caller), e.g. the head joints that
     * the agent's Scan or Track actions (4.6.1) drive while a motion plays; NaN removes the command.
     */
    public JointVelocities with(Joint j, double radPerSecond) {
        double[] copy = this.radPerSecond.clone();
        copy[j.ordinal()] = radPerSecond;
        return new JointVelocities(copy);
    }

    /** Appends {@code (lle3 0.5)}... for every joint that has a command. */
    public EffectorMessage appendTo(EffectorMessage message) {
        for (Joint j : JOINTS) if (has(j)) message.hinge(j, radPerSecond[j.ordinal()]);
        return message;
    }

    /**
     * The same text as {@code with(HJ1, yaw).with(HJ2, pitch).appendTo(message)} without the two
     * copies: the head's commands replaced (NaN: none), for the agent's head control every cycle.
     */
    public EffectorMessage appendTo(EffectorMessage message, double headYawRadPerSecond, double headPitchRadPerSecond) {
        for (Joint j : JOINTS) {
            double v = j == Joint.HJ1 ? headYawRadPerSecond : j == Joint.HJ2 ? headPitchRadPerSecond : radPerSecond[j.ordinal()];
            if (!Double.isNaN(v)) message.hinge(j, v);
        }
        return message;
    }

    @Override public String toString() {
        StringBuilder sb = new StringBuilder("JointVelocities[");
        for (Joint j : Joint.values()) if (has(j)) sb.append(j.effectorName()).append('=').append(radPerSecond(j)).append(' ');
        return sb.append(']').toString();
    }

    @Override public boolean equals(Object o) { return o instanceof JointVelocities v && Arrays.equals(radPerSecond, v.radPerSecond); }
    @Override public int hashCode() { return Arrays.hashCode(radPerSecond); }
}

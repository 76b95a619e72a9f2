package phalanx.motion.t1;

/**
 * One rcssservermj joint PD command, {@code (<actuator> q_deg dq_deg kp kd tau)}: the server applies
 * tau_total = kp (q - q_actual) + kd (dq - dq_actual) + tau with q and dq converted from degrees to radians,
 * so kp is in N m / rad and kd in N m s / rad (docs/rcssservermj.md, rcsssmj sim/simulation.py).
 */
public record JointCommand(String actuator, double qDeg, double dqDeg, double kp, double kd, double tau) {
}

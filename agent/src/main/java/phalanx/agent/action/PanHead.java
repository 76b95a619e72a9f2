package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;

/**
 * 4.6.1 Pan Head: periodic panning at zero tilt. The yaw is a triangle wave of the server time,
 * so it needs no state and two calls in one cycle agree.
 */
public final class PanHead implements HeadControl {
    private final AgentConfig.Head config;

    public PanHead(AgentConfig config) { this.config = config.head(); }

    @Override
    public HeadTarget head(Situation s) { return new HeadTarget(yaw(config, s.now()), 0); }

    /** The pan's yaw at time t: -A at the start of a period, +A half way, linear in between. */
    static double yaw(AgentConfig.Head c, double t) {
        if (!Double.isFinite(t)) return 0;
        double u = phase(c, t);
        double tri = u < 0.5 ? -1 + 4 * u : 3 - 4 * u;
        return c.panAmplitudeDeg() * tri;
    }

    /** Where in the sweep, 0..1: the first half sweeps to the left. */
    static double phase(AgentConfig.Head c, double t) {
        double u = t / c.panPeriodSeconds();
        return u - Math.floor(u);
    }
}

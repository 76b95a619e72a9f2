package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;

/**
 * 4.6.1 Scan: periodic panning and tilting. The sweep to the left looks far (pitch 0), the sweep
 * back looks near the feet (pitch down), so one period covers both.
 */
public final class Scan implements HeadControl {
    private final AgentConfig.Head config;

    public Scan(AgentConfig config) { this.config = config.head(); }

    @Override
    public HeadTarget head(Situation s) {
        double t = s.now();
        if (!Double.isFinite(t)) return HeadTarget.STRAIGHT;
        double pitch = PanHead.phase(config, t) < 0.5 ? 0 : config.scanPitchDownDeg();
        return new HeadTarget(PanHead.yaw(config, t), pitch);
    }
}

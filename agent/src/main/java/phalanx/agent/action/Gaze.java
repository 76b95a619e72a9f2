package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;

/**
 * Where the head looks while the body walks somewhere: at the ball while the self belief is fresh,
 * panning for landmarks when it is not (or the ball is unknown). The thesis leaves this to each
 * action; one rule keeps localization alive during every walk.
 */
public final class Gaze {
    private final AgentConfig config;
    private final TrackObject ball;
    private final PanHead pan;

    public Gaze(AgentConfig config) {
        this.config = config;
        this.ball = TrackObject.ball(config);
        this.pan = new PanHead(config);
    }

    public HeadTarget head(Situation s) {
        if (!Facts.selfLocalized(s, config) || Facts.ball(s, config) == null) return pan.head(s);
        return ball.head(s);
    }
}

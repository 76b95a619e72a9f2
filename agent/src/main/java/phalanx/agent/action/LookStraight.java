package phalanx.agent.action;

import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Situation;

/** 4.6.1 Look Straight: both head joints to 0; the body stands. */
public final class LookStraight implements HeadControl {
    @Override
    public HeadTarget head(Situation s) { return HeadTarget.STRAIGHT; }

    @Override
    public boolean done(Situation s) { return true; }
}

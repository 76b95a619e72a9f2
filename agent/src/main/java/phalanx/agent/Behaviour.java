package phalanx.agent;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;

/** What the player does each cycle: reads the perception and writes effectors (without syn). */
public interface Behaviour {
    void think(Perception perception, EffectorMessage out);
}

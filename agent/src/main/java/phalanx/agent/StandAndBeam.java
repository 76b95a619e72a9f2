package phalanx.agent;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;

/**
 * The minimal player: beams to its kick-off spot whenever the play mode allows a beam (once per
 * such mode), and otherwise stands still. The think loop's first brain; issue 8 replaces it.
 */
public final class StandAndBeam implements Behaviour {
    private final int players;
    private int unum;
    private PlayMode beamedIn;

    public StandAndBeam(int unum, int players) {
        this.unum = unum;
        this.players = players;
    }

    @Override public void think(Perception p, EffectorMessage out) {
        if (p.gameState() == null) return;
        if (p.gameState().unum() > 0) unum = p.gameState().unum(); // the server may have chosen it
        PlayMode mode = p.gameState().playMode();
        if (mode.allowsBeam() && mode != beamedIn && unum > 0) {
            double[] spot = KickOffPositions.of(unum, players);
            out.beam(spot[0], spot[1], 0);
            beamedIn = mode;
        } else if (!mode.allowsBeam()) {
            beamedIn = null;
        }
    }
}

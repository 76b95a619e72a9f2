package phalanx.comm.perception;

import java.util.List;

/**
 * Everything one server message says. Absent parts are null (or NaN for {@code time}, empty for
 * lists). {@code unknown} keeps the raw text of perceptors this client does not understand.
 */
public record Perception(double time, GameState gameState, Vector3 gyro, Vector3 acc,
                         JointAngles joints, List<FootForce> footForces, Vision vision,
                         List<Hear> hears, List<String> unknown) {

    public boolean hasVision() { return vision != null; }
}

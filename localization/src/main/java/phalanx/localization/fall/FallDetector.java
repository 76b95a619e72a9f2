package phalanx.localization.fall;

import phalanx.comm.perception.FootForce;
import phalanx.comm.perception.Vector3;
import phalanx.localization.LocalizationConfig;

import java.util.List;

/**
 * Thesis 4.6 Stand Up's fall detection: gyro or accelerometer beyond a threshold says "possibly
 * falling"; the fall is confirmed when the torso stays tilted and the force perceptors under the
 * feet do not carry the robot (their sole-normal forces add up to less than a threshold; a robot
 * lying on its back still touches the ground with its heels, sideways to the soles). A tilt that lasts
 * {@code fallStuckCycles} is a fall whatever the feet say (a kneeling or sitting robot).
 * One call per cycle; no allocation.
 */
public final class FallDetector {
    private final double cosTilt, gyroLimit, support, sinBack;
    private final int confirmCycles, tiltCycles, stuckCycles;
    private FallState state = FallState.STANDING;
    private int downCycles, tiltedCycles;

    public FallDetector(LocalizationConfig c) {
        cosTilt = Math.cos(Math.toRadians(c.fallTiltDeg()));
        gyroLimit = c.fallGyroDegPerSec();
        support = c.fallSupportNewtons();
        confirmCycles = c.fallConfirmCycles();
        tiltCycles = c.fallTiltCycles();
        stuckCycles = c.fallStuckCycles();
        sinBack = Math.sin(Math.toRadians(c.fallBackMinDeg()));
    }

    /**
     * @param acc   accelerometer, server torso frame (+x right, +y forward, +z up), m/s²; null keeps the state
     * @param gyro  gyro rates, °/s; may be null
     * @param feet  this cycle's force perceptors (absent ones are not touching)
     */
    public FallState update(Vector3 acc, Vector3 gyro, List<FootForce> feet) {
        if (acc == null || !acc.isFinite()) return state;
        double n = acc.norm();
        if (n < 1.0) return state;                       // no gravity reading yet (first messages)
        boolean tilted = acc.z() / n < cosTilt;
        tiltedCycles = tilted ? tiltedCycles + 1 : 0;
        boolean spinning = gyro != null && gyro.isFinite()
                && Math.max(Math.abs(gyro.x()), Math.abs(gyro.y())) > gyroLimit;
        double carried = 0;
        if (feet != null) {
            for (int i = 0; i < feet.size(); i++) {
                Vector3 f = feet.get(i).force();
                if (f != null && f.isFinite() && f.z() > 0) carried += f.z();
            }
        }
        if (tilted && (carried < support || tiltedCycles >= stuckCycles)) {
            if (++downCycles >= confirmCycles) {
                // the accelerometer's y is the forward axis' share of "up": face up only if clearly positive;
                // a side-lying robot (y near 0) gets the front get-up, which rolls it onto its front
                state = acc.y() > sinBack * n ? FallState.FALLEN_BACK : FallState.FALLEN_FRONT;
                return state;
            }
        } else {
            downCycles = 0;
        }
        // A single tilted reading is a foot impact of the walk, not a fall (LocalizationConfig.fallTiltCycles).
        state = tiltedCycles >= tiltCycles || spinning ? FallState.FALLING : FallState.STANDING;
        return state;
    }

    public FallState state() { return state; }
}

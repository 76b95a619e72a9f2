package phalanx.agent.decide;

/** Where the head should point: neck yaw (hj1, + left) and pitch (hj2, + up), in degrees. */
public record HeadTarget(double yawDeg, double pitchDeg) {
    public static final HeadTarget STRAIGHT = new HeadTarget(0, 0);

    public HeadTarget {
        // The Nao's neck: yaw ±120°, pitch -45..45° (naoneckhead.rsg).
        yawDeg = Math.max(-120, Math.min(120, yawDeg));
        pitchDeg = Math.max(-45, Math.min(45, pitchDeg));
    }
}

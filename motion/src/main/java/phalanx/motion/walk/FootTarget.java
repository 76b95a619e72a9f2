package phalanx.motion.walk;

/**
 * Where the walk wants one ankle, relative to the torso centre in the horizontal (not leaning)
 * frame that turns with the torso.
 *
 * @param forward metres ahead of the torso centre
 * @param left    metres to the left of the torso centre (the left foot's is positive)
 * @param lift    metres above the ground (0 = on the ground)
 * @param yawDeg  the foot's yaw relative to the torso, counter-clockwise positive
 */
public record FootTarget(double forward, double left, double lift, double yawDeg) {}

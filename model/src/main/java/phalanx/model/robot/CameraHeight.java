package phalanx.model.robot;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;

/**
 * Camera height from the leg joints along the sagittal plane (4.6, Walk to Ball): from the ankle
 * of a flat foot up through AnklePitch, KneePitch and HipPitch to the torso and the camera. The
 * leg that stands higher is the one carrying the robot.
 */
public final class CameraHeight {
    private CameraHeight() {}

    /** Height of the camera above the ground in metres, assuming flat feet and an upright head. */
    public static double of(NaoModel g, JointAngles joints) {
        double left = leg(g, joints.degrees(Joint.LLJ3), joints.degrees(Joint.LLJ4), joints.degrees(Joint.LLJ5));
        double right = leg(g, joints.degrees(Joint.RLJ3), joints.degrees(Joint.RLJ4), joints.degrees(Joint.RLJ5));
        if (Double.isNaN(left)) return right;
        if (Double.isNaN(right)) return left;
        return Math.max(left, right);
    }

    private static double leg(NaoModel g, double hipDeg, double kneeDeg, double ankleDeg) {
        // Segment tilts from the vertical, walking up from the flat foot: shank -ankle, thigh -ankle-knee, torso -ankle-knee-hip.
        double shank = Math.toRadians(-ankleDeg);
        double thigh = shank - Math.toRadians(kneeDeg);
        double torso = thigh - Math.toRadians(hipDeg);
        return g.ankleAboveSole() + g.shank() * Math.cos(shank) + g.thigh() * Math.cos(thigh)
                + (g.hipBelowTorso() + g.cameraAboveTorso()) * Math.cos(torso);
    }

    /** Ground distance to an object on the ground seen at {@code distance} metres from the camera. */
    public static double groundDistance(double distance, double cameraHeight) {
        return Math.sqrt(Math.max(0, distance * distance - cameraHeight * cameraHeight));
    }
}

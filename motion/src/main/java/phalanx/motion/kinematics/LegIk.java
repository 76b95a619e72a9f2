package phalanx.motion.kinematics;

import phalanx.model.robot.NaoModel;
/**
 * Inverse kinematics of one leg with the hip yaw-pitch at 0 and the foot kept parallel to the
 * torso. Frame of the simulator's Nao (naoleg.rsg): x right, y forward, z up; a positive hip pitch
 * swings the thigh forward, the knee bends negative, a positive ankle pitch lifts the toes, and a
 * positive hip roll moves the leg to the robot's left (both legs).
 */
public final class LegIk {
    private LegIk() {}

    /** Joint angles in degrees: hip roll (lj2), hip pitch (lj3), knee (lj4), ankle pitch (lj5), ankle roll (lj6). */
    public record LegAngles(double hipRoll, double hipPitch, double knee, double anklePitch, double ankleRoll) {}

    /**
     * The angles that put the ankle at {@code forward}, {@code left}, {@code down} metres from the
     * hip joint. Out-of-reach targets are pulled in to the stretched leg.
     */
    public static LegAngles solve(NaoModel g, double forward, double left, double down) {
        double roll = Math.atan2(left, down);            // positive roll moves the foot to the left
        double planeDown = Math.hypot(left, down);        // hip to ankle in the leg's plane
        double a = g.thigh(), b = g.shank();
        double len = Math.min(Math.hypot(forward, planeDown), a + b);
        len = Math.max(len, Math.abs(a - b) + 1e-9);
        double kneeInner = Math.acos(clamp((a * a + b * b - len * len) / (2 * a * b)));
        double knee = -(Math.PI - kneeInner);
        double alpha = Math.acos(clamp((a * a + len * len - b * b) / (2 * a * len)));
        double hipPitch = Math.atan2(forward, planeDown) + alpha;
        double anklePitch = -(hipPitch + knee);
        return new LegAngles(Math.toDegrees(roll), Math.toDegrees(hipPitch), Math.toDegrees(knee),
                Math.toDegrees(anklePitch), -Math.toDegrees(roll));
    }

    /** Forward kinematics of the same chain: the ankle's (forward, left, down) from the hip, metres. */
    public static double[] ankle(NaoModel g, LegAngles q) {
        double h = Math.toRadians(q.hipPitch()), k = Math.toRadians(q.knee()), r = Math.toRadians(q.hipRoll());
        double forward = g.thigh() * Math.sin(h) + g.shank() * Math.sin(h + k);
        double planeDown = g.thigh() * Math.cos(h) + g.shank() * Math.cos(h + k);
        return new double[] {forward, planeDown * Math.sin(r), planeDown * Math.cos(r)};
    }

    private static double clamp(double c) { return Math.max(-1, Math.min(1, c)); }
}

package phalanx.motion.t1;

import java.util.ArrayList;
import java.util.List;

/**
 * Every number of the T1 kick ({@link T1Kick}). Offsets are in the torso frame (x forward, y left, z up, metres)
 * relative to the gait's stand pose ({@link T1GaitConfig#footX()}, footY, footZ); a kick is written for the right
 * foot and mirrored for the left. Starting values were set by hand from robot.xml's geometry (foot box half length
 * 0.1115 m at x +0.01 of the ankle, ball radius 0.11 m, soccer_ball.py), then a few changed by hand after bench
 * runs (sway 0.075 fell over the support foot, supportX 0 fell backwards, a 0.10 s swing the foot did not follow);
 * the values marked "search" come from a (1+1) random search with {@code scripts/phalanx bench t1 --trial kick}
 * on rcssservermj (217 rounds, 12 values, 3 perturbed per candidate; score = mean over 4 kicks, both feet, ball up
 * to 2 cm off its spot, of distance - 0.04 m per degree of direction error, -3 for a fall; motion/README.md,
 * "T1 kick"), its start being the hand-set values in brackets.
 *
 * @param phases   the keyframes, played in order; each is reached linearly from the one before (the first from
 *                 the stand pose); the last must be the stand pose (all zero) so the gait can take over
 * @param legKp    hip and knee stiffness during the kick, N m / rad
 * @param legKd    hip and knee damping, N m s / rad
 * @param ankleKp  ankle stiffness, N m / rad
 * @param ankleKd  ankle damping, N m s / rad
 * @param ballX    where the ball's centre should be for the kick: ahead of the torso origin, m
 * @param ballY    ... and sideways from the torso origin towards the kicking foot, m
 * @param directionDeg where the ball goes, against the heading at the kick's start, for the right foot (counter-
 *                 clockwise positive; the left foot's is its negative): measured with the bench, for aiming
 */
public record T1KickConfig(List<Phase> phases, double legKp, double legKd, double ankleKp, double ankleKd,
                           double ballX, double ballY, double directionDeg) {

    /**
     * One keyframe.
     *
     * @param name        for logs and tests
     * @param seconds     time to reach this keyframe from the previous one
     * @param sway        torso shift over the support foot, m (both feet move the other way in the torso frame)
     * @param kickX       kicking foot forward, m
     * @param kickY       kicking foot inwards (towards the support foot), m
     * @param kickZ       kicking foot lift, m
     * @param kickPitch   kicking ankle pitch added to the IK's level sole, rad (positive: toes down)
     * @param supportX    support foot forward, m
     */
    public record Phase(String name, double seconds, double sway, double kickX, double kickY, double kickZ,
                        double kickPitch, double supportX) {
        public Phase {
            if (!(seconds > 0)) throw new IllegalArgumentException("phase " + name + ": seconds must be > 0");
        }

        Phase with(String field, double v) {
            return switch (field) {
                case "seconds" -> new Phase(name, v, sway, kickX, kickY, kickZ, kickPitch, supportX);
                case "sway" -> new Phase(name, seconds, v, kickX, kickY, kickZ, kickPitch, supportX);
                case "kickX" -> new Phase(name, seconds, sway, v, kickY, kickZ, kickPitch, supportX);
                case "kickY" -> new Phase(name, seconds, sway, kickX, v, kickZ, kickPitch, supportX);
                case "kickZ" -> new Phase(name, seconds, sway, kickX, kickY, v, kickPitch, supportX);
                case "kickPitch" -> new Phase(name, seconds, sway, kickX, kickY, kickZ, v, supportX);
                case "supportX" -> new Phase(name, seconds, sway, kickX, kickY, kickZ, kickPitch, v);
                default -> throw new IllegalArgumentException("no T1KickConfig.Phase field " + field);
            };
        }

        boolean standPose() {
            return sway == 0 && kickX == 0 && kickY == 0 && kickZ == 0 && kickPitch == 0 && supportX == 0;
        }
    }

    public T1KickConfig {
        phases = List.copyOf(phases);
        if (phases.isEmpty() || !phases.get(phases.size() - 1).standPose())
            throw new IllegalArgumentException("a kick must end in the stand pose (last phase all zero)");
    }

    /** Total duration, s. */
    public double seconds() {
        return phases.stream().mapToDouble(Phase::seconds).sum();
    }

    public static T1KickConfig defaults() {
        return new T1KickConfig(List.of(
                //        name       s       sway    kickX   kickY  kickZ   pitch    supX
                new Phase("shift",   0.60,   0.0461, 0.00,   0.00,  0.00,   0.00,    0.00),     // search (start 0.05)
                new Phase("lift",    0.25,   0.0461, -0.04,  0.00,  0.0727, 0.00,    -0.0316),  // search (start 0.06, -0.04)
                new Phase("draw",    0.15,   0.0461, -0.22,  0.00,  0.0504, 0.00,    -0.0316),  // search (start -0.12, 0.07)
                new Phase("swing",   0.1292, 0.0461, 0.2688, 0.00,  0.06,   -0.1831, -0.0316),  // search (start 0.16 s, 0.20, 0.05, 0)
                new Phase("retract", 0.25,   0.0461, 0.0548, 0.00,  0.05,   0.00,    -0.0316),  // search (start 0.02)
                new Phase("down",    0.30,   0.040,  0.00,   0.00,  0.00,   0.00,    -0.0316),  // by hand; supX search
                new Phase("back",    0.50,   0.000,  0.00,   0.00,  0.00,   0.00,    0.00)),    // the stand pose
                200, 5, 200, 2,                                                          // the gait's gains
                0.3356, 0.0132, // search (start 0.33, 0.04; by hand 0.30, the toe 0.16 m ahead + radius + gap, pushed the
                                // ball while standing; 0.087, the foot's y, hit it off centre: the torso drifts over the
                                // support foot and takes the kicking foot inwards)
                13);            // bench, the ball on its spot: right foot +11.5..+14.2 deg, left -12.6..-14.3 (10 kicks)
    }

    /**
     * A copy with one value changed, for the bench's {@code --kick NAME=VALUE}: {@code legKp} etc., or a phase's
     * field as {@code PHASE.FIELD}, e.g. {@code swing.kickX}.
     */
    public T1KickConfig with(String name, double value) {
        int dot = name.indexOf('.');
        if (dot > 0) {
            String phase = name.substring(0, dot), field = name.substring(dot + 1);
            List<Phase> out = new ArrayList<>(phases);
            boolean found = false;
            for (int i = 0; i < out.size(); i++) {
                if (out.get(i).name().equals(phase)) {
                    out.set(i, out.get(i).with(field, value));
                    found = true;
                }
            }
            if (!found) throw new IllegalArgumentException("no kick phase " + phase);
            return new T1KickConfig(out, legKp, legKd, ankleKp, ankleKd, ballX, ballY, directionDeg);
        }
        return switch (name) {
            case "legKp" -> new T1KickConfig(phases, value, legKd, ankleKp, ankleKd, ballX, ballY, directionDeg);
            case "legKd" -> new T1KickConfig(phases, legKp, value, ankleKp, ankleKd, ballX, ballY, directionDeg);
            case "ankleKp" -> new T1KickConfig(phases, legKp, legKd, value, ankleKd, ballX, ballY, directionDeg);
            case "ankleKd" -> new T1KickConfig(phases, legKp, legKd, ankleKp, value, ballX, ballY, directionDeg);
            case "ballX" -> new T1KickConfig(phases, legKp, legKd, ankleKp, ankleKd, value, ballY, directionDeg);
            case "ballY" -> new T1KickConfig(phases, legKp, legKd, ankleKp, ankleKd, ballX, value, directionDeg);
            case "directionDeg" -> new T1KickConfig(phases, legKp, legKd, ankleKp, ankleKd, ballX, ballY, value);
            default -> throw new IllegalArgumentException("no T1KickConfig field " + name);
        };
    }
}

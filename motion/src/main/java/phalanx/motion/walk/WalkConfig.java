package phalanx.motion.walk;

/**
 * Every number of the omnidirectional walk. The thesis has no parametric walk (its walk is a
 * keyframe motion, 4.5.1, 0.45 m/s in chapter 6), so the defaults are our own, tuned in
 * rcssserver3d 0.7.3 with {@code scripts/phalanx bench walk} (motion/README.md, "Omnidirectional walk").
 *
 * <p>Gait timing: a step (one foot's swing plus the double support before it) lasts
 * {@code stepSeconds}; a full gait cycle is two steps. Lengths are metres, angles degrees.
 *
 * @param stepSeconds        duration of one step (half a gait cycle)
 * @param doubleSupport      share of a step with both feet on the ground, at its start, 0..0.8
 * @param stepHeight         swing foot's highest lift above the ground
 * @param liftExponent       lift profile stepHeight·sin(πs)^liftExponent over the swing (s = 0..1):
 *                           1 lifts and lands fast, 2 lands with no vertical speed
 * @param swingMatchGround   0..1: how much the swinging foot's speed at lift-off and touch-down
 *                           matches the ground's speed under the torso (1 = no jerk when the foot
 *                           takes or leaves the ground; 0 = it stops relative to the torso)
 * @param swingLinear        0..1: how much of the swing moves at constant speed relative to the
 *                           torso (1 = straight line at one speed: the shortest time for the hip
 *                           joints, whose speed is capped; 0 = smooth start and stop)
 * @param legExtension       hip-to-ankle height when standing, as a share of thigh + shank (the
 *                           crouch; 1 is a stretched leg, where the knee cannot absorb anything)
 * @param footForward        neutral ankle position ahead (+) of the hip; negative puts the feet
 *                           behind, i.e. the centre of mass ahead of the feet
 * @param stanceWidth        extra lateral distance of each neutral foot outside its hip
 * @param torsoLeanDeg       forward lean of the torso; the feet stay flat (ankle pitch compensates)
 * @param swayAmplitude      lateral shift of the torso over the stance foot in the middle of a
 *                           step (sine over the step; moves the centre of mass over the support)
 * @param swayLead           phase lead of the sway as a share of a step (positive = earlier)
 * @param maxForward         forward speed limit, m/s (requests are clamped to it)
 * @param maxBackward        backward speed limit, m/s (positive number)
 * @param maxLeft            sideways speed limit, m/s, both directions
 * @param maxTurnDeg         turn-rate limit, deg/s, both directions
 * @param accelForward       forward acceleration limit, m/s²
 * @param accelLeft          sideways acceleration limit, m/s²
 * @param accelTurnDeg       turn acceleration limit, deg/s²
 * @param decelForward       forward deceleration limit (slowing toward zero), m/s²: a turn in place
 *                           asked at full speed waits for the forward speed to drop
 * @param turnAtFullSpeedDeg turn rate allowed at maxForward; the allowed rate rises linearly to
 *                           maxTurnDeg at zero forward speed, and a request turning faster gets the
 *                           forward speed at which its turn is allowed (maxTurnDeg = no coupling).
 *                           Applied to the walk's own velocity, so a turn asked while still fast
 *                           grows only as the walk slows down (the game's walk/turn alternation)
 * @param maxFootYawDeg      largest yaw of a foot relative to the torso (outward only)
 * @param servoGain          share of the remaining joint error commanded per cycle (1 = reach
 *                           the target in one cycle, as the keyframe controller does)
 * @param gyroPitchGain      ankle pitch correction, deg per deg/s of torso pitch rate (gyro x)
 * @param gyroRollGain       hip roll correction, deg per deg/s of torso roll rate (gyro y)
 * @param gyroYawGain        heading hold: deg/s of turn added per degree of heading error, the
 *                           error being the gyro's yaw (z) rate minus the commanded turn rate,
 *                           integrated while walking (the feet slip in yaw; this keeps the line)
 * @param tiltPlaceForward   foot placement from torso tilt: the swinging foot lands this many metres
 *                           further ahead per degree the torso leans forward beyond torsoLeanDeg
 *                           (tilt from the gyro and accelerometer, complementary filter)
 * @param tiltPlaceLeft      the same sideways: metres further to the robot's right per degree of
 *                           roll to the right
 * @param tiltHipPitch       hip pitch correction, degrees per degree of forward lean beyond
 *                           torsoLeanDeg (negative straightens a torso that leans too far)
 * @param armSwingDeg        shoulder pitch swing per metre of the opposite foot's forward offset
 * @param odometryForward    measured forward distance per commanded distance (the odometry scale)
 * @param odometryLeft       measured sideways distance per commanded distance
 * @param odometryTurn       measured turn per commanded turn
 */
public record WalkConfig(double stepSeconds, double doubleSupport, double stepHeight, double liftExponent,
                         double swingMatchGround, double swingLinear, double legExtension,
                         double footForward, double stanceWidth, double torsoLeanDeg, double swayAmplitude,
                         double swayLead, double maxForward, double maxBackward, double maxLeft, double maxTurnDeg,
                         double accelForward, double accelLeft, double accelTurnDeg, double decelForward,
                         double turnAtFullSpeedDeg, double maxFootYawDeg,
                         double servoGain, double gyroPitchGain, double gyroRollGain, double gyroYawGain,
                         double tiltPlaceForward, double tiltPlaceLeft, double tiltHipPitch, double armSwingDeg,
                         double odometryForward, double odometryLeft, double odometryTurn) {

    /** Names of the fields in declaration order (for {@link #with}); first, the per-type configs below use it. */
    public static final java.util.List<String> FIELDS = java.util.Arrays.stream(WalkConfig.class.getRecordComponents())
            .map(java.lang.reflect.RecordComponent::getName).toList();

    /** Each field's allowed range [min, max] (the constructor refuses a value outside); before DEFAULT, which is checked against it. */
    private static final java.util.Map<String, double[]> RANGES = java.util.Map.ofEntries(
            java.util.Map.entry("stepSeconds", new double[] {0.04, 1.0}),
            java.util.Map.entry("doubleSupport", new double[] {0, 0.8}),
            java.util.Map.entry("stepHeight", new double[] {0, 0.1}),
            java.util.Map.entry("liftExponent", new double[] {0.5, 4}),
            java.util.Map.entry("swingMatchGround", new double[] {0, 1.5}),
            java.util.Map.entry("swingLinear", new double[] {0, 1}),
            java.util.Map.entry("legExtension", new double[] {0.5, 1.0}),
            java.util.Map.entry("footForward", new double[] {-0.1, 0.1}),
            java.util.Map.entry("stanceWidth", new double[] {-0.02, 0.1}),
            java.util.Map.entry("torsoLeanDeg", new double[] {-30, 45}),
            java.util.Map.entry("swayAmplitude", new double[] {0, 0.1}),
            java.util.Map.entry("swayLead", new double[] {-0.5, 0.5}),
            java.util.Map.entry("maxForward", new double[] {0, 3}),
            java.util.Map.entry("maxBackward", new double[] {0, 3}),
            java.util.Map.entry("maxLeft", new double[] {0, 3}),
            java.util.Map.entry("maxTurnDeg", new double[] {0, 720}),
            java.util.Map.entry("accelForward", new double[] {1e-3, 100}),
            java.util.Map.entry("accelLeft", new double[] {1e-3, 100}),
            java.util.Map.entry("accelTurnDeg", new double[] {1e-3, 10000}),
            java.util.Map.entry("decelForward", new double[] {1e-3, 100}),
            java.util.Map.entry("turnAtFullSpeedDeg", new double[] {0, 720}),
            java.util.Map.entry("maxFootYawDeg", new double[] {0, 80}),
            java.util.Map.entry("servoGain", new double[] {0.05, 1.5}),
            java.util.Map.entry("gyroPitchGain", new double[] {-1, 1}),
            java.util.Map.entry("gyroRollGain", new double[] {-1, 1}),
            java.util.Map.entry("gyroYawGain", new double[] {0, 20}),
            java.util.Map.entry("tiltPlaceForward", new double[] {-0.05, 0.05}),
            java.util.Map.entry("tiltPlaceLeft", new double[] {-0.05, 0.05}),
            java.util.Map.entry("tiltHipPitch", new double[] {-5, 5}),
            java.util.Map.entry("armSwingDeg", new double[] {-2000, 2000}),
            java.util.Map.entry("odometryForward", new double[] {0, 2}),
            java.util.Map.entry("odometryLeft", new double[] {0, 2}),
            java.util.Map.entry("odometryTurn", new double[] {0, 2}));

    /** The tuned walk (see motion/README.md for the measured figures and the command). */
    public static final WalkConfig DEFAULT = new WalkConfig(
            // timing and swing: stepSeconds, doubleSupport, stepHeight, liftExponent, swingMatchGround, swingLinear
            0.12, 0.0, 0.021, 1.0, 0.4, 0.0,
            // posture: legExtension, footForward, stanceWidth, torsoLeanDeg, swayAmplitude, swayLead
            0.88, -0.01, 0.0, 6.0, 0.007, 0.0,
            // limits: maxForward, maxBackward, maxLeft, maxTurnDeg, accelForward, accelLeft, accelTurnDeg,
            // decelForward, turnAtFullSpeedDeg, maxFootYawDeg
            0.88, 0.4, 0.1, 90, 0.4, 1.0, 200, 0.8, 0, 40,
            // feedback: servoGain, gyroPitchGain, gyroRollGain, gyroYawGain, tiltPlaceForward, tiltPlaceLeft, tiltHipPitch
            1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
            // armSwingDeg; odometry scales forward, left, turn
            75, 1.0, 1.0, 1.0);

    /**
     * The tuned walk for robot type 0-4 (-1 = nao.rsg = type 0). Types 0, 2 and 4 (the same legs)
     * share the default; the long-legged types 1 and 3 use it too until a tuning of their own
     * measures better (motion/README.md).
     */
    public static WalkConfig forType(int type) {
        return switch (type) {
            case -1, 0, 4 -> DEFAULT;
            case 1, 2, 3 -> TYPE_OVERRIDES.getOrDefault(type, DEFAULT);
            default -> throw new IllegalArgumentException("robot type must be 0-4 (or -1 for nao.rsg), got " + type);
        };
    }

    /** Types whose own tuning measured better than the default (none at present; see forType). */
    private static final java.util.Map<Integer, WalkConfig> TYPE_OVERRIDES = java.util.Map.of();

    public WalkConfig {
        range(stepSeconds, "stepSeconds");
        range(doubleSupport, "doubleSupport");
        range(stepHeight, "stepHeight");
        range(liftExponent, "liftExponent");
        range(swingMatchGround, "swingMatchGround");
        range(swingLinear, "swingLinear");
        range(legExtension, "legExtension");
        range(footForward, "footForward");
        range(stanceWidth, "stanceWidth");
        range(torsoLeanDeg, "torsoLeanDeg");
        range(swayAmplitude, "swayAmplitude");
        range(swayLead, "swayLead");
        range(maxForward, "maxForward");
        range(maxBackward, "maxBackward");
        range(maxLeft, "maxLeft");
        range(maxTurnDeg, "maxTurnDeg");
        range(accelForward, "accelForward");
        range(accelLeft, "accelLeft");
        range(accelTurnDeg, "accelTurnDeg");
        range(decelForward, "decelForward");
        range(turnAtFullSpeedDeg, "turnAtFullSpeedDeg");
        range(maxFootYawDeg, "maxFootYawDeg");
        range(servoGain, "servoGain");
        range(gyroPitchGain, "gyroPitchGain");
        range(gyroRollGain, "gyroRollGain");
        range(gyroYawGain, "gyroYawGain");
        range(tiltPlaceForward, "tiltPlaceForward");
        range(tiltPlaceLeft, "tiltPlaceLeft");
        range(tiltHipPitch, "tiltHipPitch");
        range(armSwingDeg, "armSwingDeg");
        range(odometryForward, "odometryForward");
        range(odometryLeft, "odometryLeft");
        range(odometryTurn, "odometryTurn");
    }

    private static void range(double v, String name) {
        double min = RANGES.get(name)[0], max = RANGES.get(name)[1];
        if (!(v >= min && v <= max)) throw new IllegalArgumentException("walk config " + name + " must be in [" + min + ", " + max + "], got " + v);
    }

    /** The range [min, max] a field may take (a copy); an unknown name is refused with a message naming it. */
    public static double[] range(String field) {
        double[] r = RANGES.get(field);
        if (r == null) throw new IllegalArgumentException("walk config has no field '" + field + "' (fields: " + FIELDS + ")");
        return r.clone();
    }


    /** The value of a field by name. */
    public double get(String field) {
        try {
            return (double) WalkConfig.class.getMethod(field).invoke(this);
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException("walk config has no field '" + field + "' (fields: " + FIELDS + ")");
        }
    }

    /** A copy with one field changed; an unknown name or a value out of range is refused with a message. */
    public WalkConfig with(String field, double value) {
        int k = FIELDS.indexOf(field);
        if (k < 0) throw new IllegalArgumentException("walk config has no field '" + field + "' (fields: " + FIELDS + ")");
        Object[] v = new Object[FIELDS.size()];
        for (int i = 0; i < v.length; i++) v[i] = i == k ? value : get(FIELDS.get(i));
        try {
            return (WalkConfig) WalkConfig.class.getDeclaredConstructors()[0].newInstance(v);
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw (RuntimeException) e.getCause();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(e);
        }
    }

    /** {@code name=value} pairs of every field, for logs and the README. */
    public String describe() {
        StringBuilder sb = new StringBuilder();
        for (String f : FIELDS) sb.append(sb.length() == 0 ? "" : " ").append(f).append('=').append(get(f));
        return sb.toString();
    }
}

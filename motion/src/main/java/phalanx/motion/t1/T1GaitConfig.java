package phalanx.motion.t1;

/**
 * Every constant of the T1 gait. Geometry is read from rcsssmj 0.2.1 resources/robots/T1/robot.xml (body
 * {@code pos} attributes); gait values were tuned on rcssservermj with {@code scripts/phalanx bench t1}
 * (motion/README.md, "T1 gait (rcssservermj)").
 *
 * @param waistX            torso origin to the Waist body, x (robot.xml Waist pos 0.0625 0 -0.1155)
 * @param waistZ            torso origin to the Waist body, z
 * @param hipY              Waist to Hip_Pitch_Left/Right, |y| (pos 0 ±0.106 0)
 * @param hipPitchToRoll    Hip_Pitch to Hip_Roll, -z (pos 0 0 -0.02)
 * @param hipRollToYaw      Hip_Roll to Hip_Yaw, -z (pos 0 0 -0.081854)
 * @param yawToKneeX        Hip_Yaw to Shank (knee), x (pos -0.014 0 -0.134)
 * @param yawToKneeZ        Hip_Yaw to Shank (knee), -z
 * @param shank             Shank to Ankle_Cross (ankle pitch), -z (pos 0 0 -0.28)
 * @param anklePitchToRoll  Ankle_Cross to foot_link (ankle roll), -z (pos 0 ±0.00025 -0.012)
 * @param anklePitchToRollY Ankle_Cross to foot_link, |y|
 * @param soleDepth         foot_link frame to the sole (foot box pos z -0.015, half height 0.015)
 * @param footX             foot frame x in the torso frame when standing (m; straight leg: 0.0485)
 * @param footY             foot frame |y| in the torso frame when standing (m; straight leg: 0.10625)
 * @param footZ             foot frame z in the torso frame when standing (m; straight leg: -0.6434), the crouch
 * @param stepTime          one step (half a gait cycle), s
 * @param doubleSupport     fraction of a step with both feet down
 * @param sway              lateral torso sway amplitude over the support foot, m
 * @param lift              swing foot lift height, m
 * @param maxVx             forward speed limit, m/s (backward: half of it)
 * @param maxVy             sideways speed limit, m/s
 * @param maxTurn           turn rate limit, deg/s
 * @param accel             command ramp, m/s per s (turn: 10 x this in deg/s per s)
 * @param legKp             hip and knee stiffness, N m / rad (booster_gym's T1 value 200)
 * @param legKd             hip and knee damping, N m s / rad
 * @param ankleKp           ankle stiffness, N m / rad
 * @param ankleKd           ankle damping, N m s / rad
 * @param armKp             arms, head and waist stiffness
 * @param armKd             arms, head and waist damping
 * @param shoulderRollDeg   arms down: left shoulder roll (right mirrored), deg (0 = arms out sideways)
 * @param elbowDeg          elbow pitch, deg
 * @param pitchGain         ankle pitch correction per rad of torso pitch (rad/rad)
 * @param pitchRateGain     ankle pitch correction per rad/s of torso pitch rate
 * @param rollGain          ankle/hip roll correction per rad of torso roll
 * @param rollRateGain      ankle/hip roll correction per rad/s of torso roll rate
 * @param stepPitchGain     swing foot target x shift per rad of torso pitch error, m/rad
 * @param stepRollGain      swing foot target y shift per rad of torso roll (roll > 0: right side down), m/rad
 * @param comHeight         pendulum height for the step shapes, m (CoM about 0.55 m up when crouched)
 * @param lipmBlend         0: the support foot moves back linearly; 1: with the pendulum's sinh shape
 * @param hipPitchGain      hip pitch correction per rad of torso pitch error (rad/rad)
 * @param hipRollGain       hip roll correction per rad of torso roll (rad/rad)
 * @param torsoPitchDeg     wanted torso pitch (forward lean, deg) for the feedback's reference
 * @param dt                control cycle, s (rcssservermj: 0.02)
 * @param strideScale       forward stride per commanded speed (1: the support foot moves back at the command; the
 *                          walk goes a little slower than commanded, so a walking preset may ask for more)
 */
public record T1GaitConfig(double waistX, double waistZ, double hipY, double hipPitchToRoll, double hipRollToYaw,
                           double yawToKneeX, double yawToKneeZ, double shank, double anklePitchToRoll,
                           double anklePitchToRollY, double soleDepth,
                           double footX, double footY, double footZ,
                           double stepTime, double doubleSupport, double sway, double lift,
                           double maxVx, double maxVy, double maxTurn, double accel,
                           double legKp, double legKd, double ankleKp, double ankleKd, double armKp, double armKd,
                           double shoulderRollDeg, double elbowDeg,
                           double pitchGain, double pitchRateGain, double rollGain, double rollRateGain,
                           double stepPitchGain, double stepRollGain,
                           double comHeight, double lipmBlend,
                           double hipPitchGain, double hipRollGain,
                           double torsoPitchDeg, double dt, double strideScale) {

    /**
     * Geometry from robot.xml; gains: hips/knees booster_gym's 200, ankles raised to 200 (at 80 the 20 N m ankle
     * let the stand fall forward); arms down by hand. The gait values marked "search" came from a (1+1) random
     * search with the bench (3 fields perturbed per candidate, score = measured speed - 0.1 x falls over a
     * 20 s walk; 32 rounds at 0.4 m/s commanded from the hand-set start, then 7 at 0.6 m/s; motion/README.md).
     */
    public static T1GaitConfig defaults() {
        return new T1GaitConfig(0.0625, -0.1155, 0.106, 0.02, 0.081854,     // robot.xml
                -0.014, 0.134, 0.28, 0.012,                                  // robot.xml
                0.00025, 0.03,                                               // robot.xml
                0.0386, 0.0873, -0.5502,                                     // search (hand start 0.045, 0.106, -0.60)
                0.3050, 0.1824, 0.0226, 0.0700,                              // search (hand start 0.30, 0.2, 0.035, 0.05)
                0.8, 0.3, 90, 0.5,                                           // by hand
                200, 5, 200, 2, 60, 2,                                       // see above
                -75, 0,                                                      // by hand
                1.6653, 0.0699, -0.1480, -0.0265,                            // search (hand start 1.0, 0.05, 0, 0)
                0.1459, -0.3770,                                             // search (hand start 0, 0)
                0.55, 0.9254,                                                // CoM height estimate; search (start 1)
                0.5428, 0.3583,                                              // search (start 0, 0)
                -2.8147, 0.02,                                               // search (start 0); rcssservermj cycle
                1.0);
    }

    /**
     * A second preset from a search that scored the 20 s walk at 0.6 m/s and the 20 s turn at 60 deg/s together
     * (score = speed - 0.1 x falls + 0.6 x turn rate / 60 deg/s - 0.1 x turn falls; 48 rounds from
     * {@link #defaults()}): it turns on the spot without falling but walks slower (motion/README.md).
     */
    public static T1GaitConfig balanced() {
        return defaults().with("stepTime", 0.3037).with("sway", 0.0267).with("footZ", -0.52).with("footX", 0.03)
                .with("doubleSupport", 0.0091).with("pitchGain", 1.6287).with("pitchRateGain", 0.0447)
                .with("rollGain", -0.083).with("rollRateGain", -0.0911).with("stepPitchGain", 0.0)
                .with("stepRollGain", -0.2858).with("lipmBlend", 0.9634).with("hipRollGain", 0.5538)
                .with("torsoPitchDeg", -3.0746)
                .with("maxTurn", 120); // it turns about half the command: 120 commanded gave 57.6 deg/s without a fall
    }

    /**
     * For turning on the spot only: 26 rounds of the search from {@link #balanced()} scoring the 20 s turn at
     * 120 deg/s commanded alone (score = turn rate / 60 deg/s - 0.1 x falls). It walks badly (0.6 m/s
     * commanded: 0.33 m/s with 12-13 falls in 60 s), so it is not a walking preset.
     */
    public static T1GaitConfig turnInPlace() {
        return balanced().with("stepTime", 0.2825).with("sway", 0.0374).with("footX", 0.0323).with("footY", 0.0923)
                .with("doubleSupport", 0.0).with("pitchGain", 1.7554).with("pitchRateGain", 0.0442)
                .with("rollRateGain", -0.1).with("lipmBlend", 0.6968).with("torsoPitchDeg", -5.0);
    }

    /**
     * This config moved {@code share} of the way to {@code other}, every field linearly (0: this, 1: other). The
     * geometry fields are the same in every preset, so only the gait values change.
     */
    public T1GaitConfig lerp(T1GaitConfig other, double share) {
        java.lang.reflect.RecordComponent[] rc = T1GaitConfig.class.getRecordComponents();
        Object[] args = new Object[rc.length];
        Class<?>[] types = new Class<?>[rc.length];
        try {
            for (int i = 0; i < rc.length; i++) {
                types[i] = double.class;
                double a = (double) rc[i].getAccessor().invoke(this), b = (double) rc[i].getAccessor().invoke(other);
                args[i] = share <= 0 ? a : share >= 1 ? b : a + (b - a) * share;
            }
            return T1GaitConfig.class.getDeclaredConstructor(types).newInstance(args);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Two presets the gait blends by the command (issue 20: no single preset both walks 0.6 m/s and turns 60 deg/s):
     * {@code walk} for walking, {@code turn} for turning on the spot. The turn share of a command is
     * {@code a / (a + b)}, a = |turn| / turn.maxTurn(), b = |(vx / walk.maxVx(), vy / walk.maxVy())| (on the ramped
     * commands); below {@code stepOnSpot} for a + b the share is kept (stepping on the spot has no direction). The
     * share moves at most {@code ratePerS} per second. Walking and turning fast do not mix (the walk preset falls
     * turning, the turn preset walking; bench t1 walkturn fell 11-16 times in 60 s when both ramped at once): at a speed
     * of {@code fullSpeed} m/s or more the ramped turn is held within {@code turnAtSpeed} deg/s, at 0 the turn
     * preset's maxTurn, linearly between, and the speed grows only as far as the turn allows; so a switch from walking
     * to turning first slows down, and one from turning to walking first stops turning.
     */
    public record Blend(T1GaitConfig walk, T1GaitConfig turn, double ratePerS, double stepOnSpot,
                        double turnAtSpeed, double fullSpeed, double decel) {
        /**
         * The agent's: defaults() to walk, turnInPlace() to turn (motion/README.md "T1 gait", blend). ratePerS 5: at 1
         * the turn trial fell 20 times in 60 s (turning fast on the walk preset while the share grew), at 5 none;
         * turnAtSpeed 30: defaults() turned 30 deg/s commanded on the spot without a fall.
         */
        public static Blend agent() {
            return new Blend(balancedWalk(), turnInPlace(), 5.0, 0.05, 10, 0.15, 0.2);
        }

        /** The largest turn rate (deg/s) allowed at this speed (m/s). */
        public double allowedTurn(double speed) {
            double free = Math.max(0, 1 - Math.abs(speed) / fullSpeed);
            return turnAtSpeed + (Math.max(walk.maxTurn(), turn.maxTurn()) - turnAtSpeed) * free;
        }

        public Blend withRate(double r) { return new Blend(walk, turn, r, stepOnSpot, turnAtSpeed, fullSpeed, decel); }
        public Blend withWalk(T1GaitConfig w) { return new Blend(w, turn, ratePerS, stepOnSpot, turnAtSpeed, fullSpeed, decel); }
        public Blend withTurn(T1GaitConfig t) { return new Blend(walk, t, ratePerS, stepOnSpot, turnAtSpeed, fullSpeed, decel); }
        public Blend withTurnAtSpeed(double deg, double speed) { return new Blend(walk, turn, ratePerS, stepOnSpot, deg, speed, decel); }
        public Blend withDecel(double d) { return new Blend(walk, turn, ratePerS, stepOnSpot, turnAtSpeed, fullSpeed, d); }
    }

    /**
     * {@link #balanced()} with a longer stride: it walks 0.502 m/s at 0.6 commanded, stride 1.2 x the command 0.602
     * and 1.25 x 0.627 m/s, no fall in 60 s (bench t1 --preset balanced --set strideScale=1.25, 2026-12-08). The
     * blend's walk preset: it is steadier than {@link #defaults()} after a switch from turning (defaults() fell 5-9
     * times in the 60 s walkturn trial) and near {@link #turnInPlace()}, which was searched from it.
     */
    public static T1GaitConfig balancedWalk() {
        return balanced().with("strideScale", 1.25);
    }

    /**
     * The recovery stand after a get-up ({@link T1GetUp}): {@link #balanced()}'s stand pose, where the get-up motions
     * end, as it is; the two changes of its feedback measured for the landing made it worse (motion/README.md "First try").
     */
    public static T1GaitConfig getUpRecovery() {
        return balanced();
    }

    /** A copy with a named field changed (for the bench's --set name=value). */
    public T1GaitConfig with(String name, double value) { return phalanx.motion.RecordFields.withDouble(this, name, value); }
}

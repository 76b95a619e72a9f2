package phalanx.agent.act;

import phalanx.agent.decide.Move;
import phalanx.comm.perception.Perception;
import phalanx.motion.MotionConfig;
import phalanx.motion.control.JointVelocities;
import phalanx.motion.control.MotionController;
import phalanx.motion.walk.Odometry;
import phalanx.motion.walk.WalkConfig;
import phalanx.motion.walk.WalkController;
import phalanx.motion.walk.WalkVelocity;

/**
 * Carries out a {@link Move}: walking, turning and side steps with the omnidirectional walk
 * (motion.walk), kicks, stand-ups and dives with the keyframe motions (motion.control). A kick
 * waits until the walk has stopped; a stand-up or dive takes over at once; after a keyframe motion
 * the walk starts afresh from standing.
 */
public final class Body {
    private final MotionController keyframes;
    private final WalkConfig walkConfig;
    private final MotionConfig motionConfig;
    private final int robotType;
    private WalkController walk;
    private boolean keyframeUsed;
    private final int standBeforeCycles, standAfterCycles;   // MotionConfig's stand times, in cycles
    private int standAfterLeft;   // cycles the new walk still stands after a keyframe motion
    private int stoodFor;         // cycles the walk has stood still (not stepping) in a row
    private Odometry odometry = Odometry.NONE;

    public Body(MotionController keyframes, WalkConfig walkConfig, MotionConfig motionConfig, int robotType) {
        this.keyframes = keyframes;
        this.walkConfig = walkConfig;
        this.motionConfig = motionConfig;
        this.robotType = robotType;
        this.standBeforeCycles = motionConfig.standBeforeCycles();
        this.standAfterCycles = motionConfig.standAfterCycles();
        this.walk = newWalk();
    }

    public MotionController keyframes() { return keyframes; }

    /** This cycle's motion as the walk commanded it (zero while a keyframe motion plays). */
    public Odometry odometry() { return odometry; }

    public JointVelocities step(Perception p, Move move) {
        WalkVelocity wanted = velocity(move);
        boolean urgent = move instanceof Move.StandUp || move instanceof Move.Dive;
        odometry = Odometry.NONE;
        if (wanted != null && keyframes.playing() == null) {
            if (keyframeUsed) {       // after a kick, a fall or a dive the gait starts from standing ...
                walk = newWalk();
                walk.startFrom(p.joints(), standAfterCycles);
                keyframeUsed = false;
                standAfterLeft = standAfterCycles;
            }
            if (standAfterLeft > 0) { // ... and stands, easing into its crouch, a moment before it steps (MotionConfig)
                standAfterLeft--;
                wanted = WalkVelocity.ZERO;
            }
            return walkStep(p, wanted);
        }
        // stop before kicking, and stand still a moment (MotionConfig.standBeforeSeconds); the quick kick is for a
        // pressed player and goes as soon as the walk has stopped
        boolean quick = move instanceof Move.Kick k && k.quick();
        if (wanted == null && !urgent && !keyframeUsed && (walk.walking() || !quick && stoodFor < standBeforeCycles)) {
            return walkStep(p, WalkVelocity.ZERO);
        }
        keyframeUsed = true;
        return keyframes.step(p.time(), p.joints(), p.acc(), Locomotion.request(wanted == null ? move : Move.STAND));
    }

    private JointVelocities walkStep(Perception p, WalkVelocity wanted) {
        boolean wasWalking = walk.walking();
        JointVelocities v = walk.step(p.joints(), p.gyro(), p.acc(), wanted);
        odometry = walk.odometry();
        stoodFor = wasWalking || walk.walking() ? 0 : stoodFor + 1;   // whole cycles of standing
        return v;
    }

    /** Share of the walk's backward speed limit for {@link Move.StepBack}: a few centimetres, not a retreat. */
    private static final double STEP_BACK_SHARE = 0.5;

    /** The walk velocity for a locomotion move, ZERO for standing, null for a keyframe move. */
    private WalkVelocity velocity(Move move) {
        if (move instanceof Move.Stand) return WalkVelocity.ZERO;
        if (move instanceof Move.Walk w) {
            // Walk Leaning (4.5.5) becomes a turn rate while walking; Walk Slowdown a slower pace.
            double forward = walkConfig.maxForward() * (w.slow() ? 0.4 : 1.0);
            return new WalkVelocity(forward, 0, w.lean() * 0.5 * walkConfig.maxTurnDeg());
        }
        if (move instanceof Move.Turn t) return new WalkVelocity(0, 0, (t.left() ? 1 : -1) * t.gain() * walkConfig.maxTurnDeg());
        if (move instanceof Move.Omni o) {
            double forward = o.forward() * (o.forward() >= 0 ? walkConfig.maxForward() : walkConfig.maxBackward());
            return new WalkVelocity(forward, o.left() * walkConfig.maxLeft(), o.turn() * walkConfig.maxTurnDeg());
        }
        if (move instanceof Move.SideStep s) return new WalkVelocity(0, (s.left() ? 1 : -1) * walkConfig.maxLeft(), 0);
        if (move instanceof Move.StepBack) return new WalkVelocity(-STEP_BACK_SHARE * walkConfig.maxBackward(), 0, 0);
        return null;
    }

    private WalkController newWalk() {
        return new WalkController(walkConfig, robotType, motionConfig);
    }
}

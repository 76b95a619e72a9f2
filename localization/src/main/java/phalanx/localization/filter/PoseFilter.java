package phalanx.localization.filter;

import phalanx.model.field.Pose2;
import phalanx.localization.vision.LandmarkSighting;

import java.util.List;

/** A self-localization filter the belief store runs: the thesis's FIFO or the EKF (config). */
public interface PoseFilter {

    /** One cycle of own motion (odometry) in the body frame: metres forward, metres left, degrees turned. */
    void predict(double forward, double left, double turnDeg);

    /**
     * A vision frame: the pair-triangulation fix (null with fewer than two landmarks) and the
     * landmarks seen. Returns true when the belief was updated by this frame.
     */
    boolean update(Pose2 fix, List<LandmarkSighting> seen);

    /** The belief, or null before the first fix. */
    Pose2 pose();

    /** 0 (no belief) to 1 (as sure as this filter gets). */
    double confidence();

    /**
     * How many times a belief began since construction: the first fix, a start after the belief was
     * lost or reset, a relocation after a move (issue 19). Whatever was placed with the old pose (the
     * ball) is wrong when this changes.
     */
    int starts();

    /** Forgets the belief (after a beam the agent asked for, for example). */
    void reset();
}

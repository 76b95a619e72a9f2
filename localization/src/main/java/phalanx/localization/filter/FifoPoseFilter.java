package phalanx.localization.filter;

import phalanx.localization.LocalizationConfig;
import phalanx.model.field.Pose2;
import phalanx.localization.vision.LandmarkSighting;

import java.util.List;

/** The thesis's self filter (4.4.3, Algorithm 1) over pair-triangulation fixes. */
public final class FifoPoseFilter implements PoseFilter {
    private final LocalizationFilter fifo;

    public FifoPoseFilter(LocalizationConfig c) {
        fifo = new LocalizationFilter(c.fifoMaxSize(), c.selfAgreementMetres(), c.selfAgreementDeg());
    }

    @Override public void predict(double forward, double left, double turnDeg) {
        if (forward != 0 || left != 0 || turnDeg != 0) fifo.shift(forward, left, turnDeg);
    }

    @Override public boolean update(Pose2 fix, List<LandmarkSighting> seen) {
        return fix != null && fifo.add(fix);
    }

    @Override public Pose2 pose() { return fifo.pose(); }

    @Override public double confidence() { return (double) fifo.size() / fifo.maxSize(); }

    @Override public void reset() { fifo.clear(); }
}

package phalanx.localization.filter;

import phalanx.localization.LocalizationConfig;
import phalanx.model.field.Pose2;
import phalanx.localization.vision.LandmarkSighting;
import phalanx.localization.vision.SelfLocalizer;

import java.util.List;

/**
 * The thesis's self filter (4.4.3, Algorithm 1) over pair-triangulation fixes, with one documented
 * addition (issue 19, not in the thesis): relocation. {@code relocateFrames} refused fixes in a row, each
 * farther than {@code relocateMetres}/{@code relocateDeg} from the belief and within
 * {@code relocateSpread*} of the one before, replace the queue (see {@link LocalizationFilter}); so does a
 * single far fix whose landmarks all agree with it ({@link SelfLocalizer#consistent}, {@code relocateResidual*}).
 */
public final class FifoPoseFilter implements PoseFilter {
    private final LocalizationFilter fifo;
    private final double residualMetres, residualShare;

    public FifoPoseFilter(LocalizationConfig c) {
        fifo = new LocalizationFilter(c.fifoMaxSize(), c.selfAgreementMetres(), c.selfAgreementDeg(),
                c.relocateFrames(), c.relocateMetres(), c.relocateDeg(), c.relocateSpreadMetres(), c.relocateSpreadDeg());
        if (!Double.isNaN(c.odometryErrorShare())) fifo.weighByMotion(c.fifoFixSigmaMetres(), c.fifoFixSigmaDeg(), c.odometryErrorShare());
        residualMetres = c.relocateResidualMetres();
        residualShare = c.relocateResidualShare();
    }

    @Override public void predict(double forward, double left, double turnDeg) {
        if (forward != 0 || left != 0 || turnDeg != 0) fifo.shift(forward, left, turnDeg);
    }

    @Override public boolean update(Pose2 fix, List<LandmarkSighting> seen) {
        return fix != null && fifo.add(fix, SelfLocalizer.consistent(fix, seen, residualMetres, residualShare));
    }

    @Override public Pose2 pose() { return fifo.pose(); }

    @Override public double confidence() { return (double) fifo.size() / fifo.maxSize(); }

    @Override public int starts() { return fifo.starts(); }

    @Override public void reset() { fifo.clear(); }
}

package phalanx.localization.mj;

import phalanx.comm.mj.MjPerception;
import phalanx.comm.perception.Vector3;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.filter.LocalizationFilter;
import phalanx.localization.vision.LandmarkSighting;
import phalanx.localization.vision.SelfLocalizer;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.model.robot.T1Model;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The thesis's self-localization (4.4.1 landmark pairs, 4.4.3 FIFO filter) on rcssservermj, to be measured against
 * the pose the server gives (docs/rcssservermj.md: the agent plays on the ground-truth torso pose, this is the check).
 * Each seen marker becomes a sighting on the level ground plane through the T1's camera chain, using only the
 * torso's roll and pitch (what an IMU gives) and the head angles, never the ground-truth yaw or position. In the
 * world frame (the left team's own frame).
 */
public final class MjSelfLocalizer {
    private final Map<String, Vector3> markers;
    private final SelfLocalizer pairs;
    private final LocalizationFilter fifo;
    private Pose2 lastFix;

    public MjSelfLocalizer(MjField field, LocalizationConfig config) {
        this.markers = field.markers();
        this.pairs = new SelfLocalizer(field.spec(), config);
        this.fifo = new LocalizationFilter(config.fifoMaxSize(), config.selfAgreementMetres(), config.selfAgreementDeg(),
                config.relocateFrames(), config.relocateMetres(), config.relocateDeg(), config.relocateSpreadMetres(),
                config.relocateSpreadDeg());
    }

    /** Feeds one perception; true when it carried a fix (two or more markers that triangulate). */
    public boolean update(MjPerception p) {
        lastFix = null;
        List<LandmarkSighting> seen = sightings(p);
        if (seen.size() < 2) return false;
        lastFix = pairs.locate(seen);
        if (lastFix == null) return false;
        fifo.add(lastFix);
        return true;
    }

    /** The markers of this perception on the level ground plane, relative to the torso, heading unknown (0). */
    List<LandmarkSighting> sightings(MjPerception p) {
        List<LandmarkSighting> out = new ArrayList<>();
        double[] yaw = p.joints().get("q_hj1"), pitch = p.joints().get("q_hj2");
        if (p.quat() == null || yaw == null || pitch == null) return out;
        double[] level = T1Model.withoutYaw(p.quat());
        double[] origin = {0, 0, 0};
        for (MjPerception.Seen s : p.seen()) {
            Vector3 at = markers.get(s.name());
            if (at == null) continue;
            double[] rel = T1Model.seenToWorld(level, origin, yaw[0], pitch[0], s.distance(), s.azimuth(), s.elevation());
            out.add(new LandmarkSighting(null, new Vector2(at.x(), at.y()), new Vector2(rel[0], rel[1])));
        }
        return out;
    }

    /** This perception's triangulated pose, or null. */
    public Pose2 lastFix() { return lastFix; }

    /** The FIFO filter's pose, or null before the first fix. */
    public Pose2 filtered() { return fifo.isEmpty() ? null : fifo.pose(); }
}

package phalanx.localization.body;

import phalanx.model.robot.NaoModel;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.Vector3;
import phalanx.comm.recording.Recordings;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.recording.GroundTruth;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Every landmark sighting of S1 (head panning ±79°) and S5 agent 7 (type 4, panning), turned into a
 * body vector by CameraPose, against the vector the ground truth torso pose predicts. Needs
 * ../shared/recordings (skipped with a message when missing).
 */
class CameraPoseRecordedTest {

    @Test
    void groundVectorsMatchTheGroundTruthWhileTheHeadPans() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        for (String name : new String[] {"S1", "S5_agent7"}) {
            List<String> lines = Recordings.perceptorMessages(Recordings.named(name));
            List<GroundTruth.Line> truth = GroundTruth.read(Recordings.groundTruthFile(Recordings.named(name)));
            PerceptionParser parser = new PerceptionParser();
            NaoModel body = NaoModel.ofType(name.equals("S1") ? 0 : 4);
            List<Double> errors = new ArrayList<>();
            double maxYaw = 0;
            for (int i = 0; i < lines.size(); i++) {
                Perception p = parser.parse(lines.get(i));
                GroundTruth.Line g = truth.get(i);
                if (!p.hasVision() || !g.hasTorso() || g.fallen()) continue;
                maxYaw = Math.max(maxYaw, Math.abs(p.joints().degrees(Joint.HJ1)));
                CameraPose c = CameraPose.of(body, p.joints(), p.acc());
                Pose2 torso = new Pose2(g.x(), g.y(), g.yawDeg());
                for (Landmark l : Landmark.values()) {
                    Polar pol = p.vision().landmark(l);
                    if (pol == null) continue;
                    Vector3 at = FieldSpec.V066.landmark(l);
                    Vector2 expected = torso.toRelative(new Vector2(at.x(), at.y()));
                    Vector3 seen = c.toBody(pol);
                    errors.add(expected.distanceTo(new Vector2(seen.x(), seen.y())));
                }
            }
            Collections.sort(errors);
            double median = errors.get(errors.size() / 2), p95 = errors.get((int) (errors.size() * 0.95));
            assertTrue(maxYaw > 60, name + ": the head really panned (" + maxYaw + "°)");
            assertTrue(errors.size() > 300, name + ": " + errors.size() + " sightings");
            System.out.printf("%s: %d sightings, ground vector error median %.3f m, p95 %.3f m%n", name, errors.size(), median, p95);
            assertTrue(median < 0.05, name + ": median " + median + " m over " + errors.size() + " sightings");
            assertTrue(p95 < 0.15, name + ": p95 " + p95 + " m");
        }
    }
}

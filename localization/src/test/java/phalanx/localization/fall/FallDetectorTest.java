package phalanx.localization.fall;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import phalanx.comm.perception.FootForce;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Vector3;
import phalanx.comm.recording.Recordings;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.Scenes;
import phalanx.comm.recording.GroundTruth;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

class FallDetectorTest {

    @Test
    void lyingFaceDownWithoutFootSupportIsAFrontFallAfterTheConfirmation() {
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        Vector3 prone = new Vector3(0, -9.81, 0.1);
        int tilt = LocalizationConfig.DEFAULT.fallTiltCycles();
        for (int i = 1; i < LocalizationConfig.DEFAULT.fallConfirmCycles(); i++)
            assertEquals(i < tilt ? FallState.STANDING : FallState.FALLING, d.update(prone, Vector3.ZERO, List.of()),
                    "cycle " + i + ": not confirmed yet");
        assertEquals(FallState.FALLEN_FRONT, d.update(prone, Vector3.ZERO, List.of()));
    }

    /** Accelerometer of a robot lying with its forward axis {@code elevDeg} above the horizontal, turned {@code rollDeg} onto a side. */
    private static Vector3 lying(double elevDeg, double rollDeg) {
        double e = Math.toRadians(elevDeg), r = Math.toRadians(rollDeg);
        // "up" seen from the torso: forward (y) share sin e, the rest along the side axis x (and a little z)
        return new Vector3(9.81 * Math.cos(e) * Math.sin(r), 9.81 * Math.sin(e), 9.81 * Math.cos(e) * Math.cos(r));
    }

    private static FallState confirmed(Vector3 acc) {
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        FallState s = null;
        for (int i = 0; i < LocalizationConfig.DEFAULT.fallConfirmCycles(); i++) s = d.update(acc, Vector3.ZERO, List.of());
        return s;
    }

    @Test
    void lyingOnASideGetsTheFrontGetUpAndOnlyAClearlyUpwardChestTheBackOne() {
        assertEquals(FallState.FALLEN_BACK, confirmed(new Vector3(0, 9.81, 0.2)), "face up");
        assertEquals(FallState.FALLEN_FRONT, confirmed(new Vector3(0, -9.81, 0.2)), "face down");
        assertEquals(FallState.FALLEN_FRONT, confirmed(lying(0, 88)), "on the left side");
        assertEquals(FallState.FALLEN_FRONT, confirmed(lying(0, -88)), "on the right side");
        assertEquals(FallState.FALLEN_FRONT, confirmed(lying(10, 85)), "on a side, chest 10 degrees up");
        assertEquals(FallState.FALLEN_FRONT, confirmed(lying(25, -85)), "chest 25 degrees up: still below the 30 degrees");
        assertEquals(FallState.FALLEN_BACK, confirmed(lying(40, 85)), "chest 40 degrees up: rolled toward the back");
        assertEquals(FallState.FALLEN_FRONT, confirmed(lying(-40, -85)), "chest 40 degrees down");
    }

    @Test
    void tiltWhileTheFeetCarryTheRobotIsNoFall() {
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        Vector3 leaning = new Vector3(0, 8, 5.7);         // 55° tilt, as in a collision
        for (int i = 1; i <= 20; i++) {
            FallState expected = i < LocalizationConfig.DEFAULT.fallTiltCycles() ? FallState.STANDING : FallState.FALLING;
            assertEquals(expected, d.update(leaning, Vector3.ZERO, Scenes.standingFeet()), "cycle " + i);
        }
        assertEquals(FallState.STANDING, d.update(Scenes.UPRIGHT, Vector3.ZERO, Scenes.standingFeet()));
    }

    @Test
    void aTiltThatLastsASecondIsAFallEvenWithTheFeetLoaded() {
        // Kneeling forward at 55° with the feet still pushing: FALLING (wait) at first, and a confirmed front fall
        // once the tilt has lasted fallStuckCycles (50) plus the confirmation (5): cycle 54 is the 5th of the
        // stuck count's confirmation (cycles 50..54).
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        Vector3 kneeling = new Vector3(0, -8, 5.7);
        int stuck = LocalizationConfig.DEFAULT.fallStuckCycles(), confirm = LocalizationConfig.DEFAULT.fallConfirmCycles();
        for (int i = 1; i < stuck + confirm - 1; i++) {
            FallState s = d.update(kneeling, Vector3.ZERO, Scenes.standingFeet());
            assertEquals(i < LocalizationConfig.DEFAULT.fallTiltCycles() ? FallState.STANDING : FallState.FALLING, s, "cycle " + i);
        }
        assertEquals(FallState.FALLEN_FRONT, d.update(kneeling, Vector3.ZERO, Scenes.standingFeet()), "cycle " + (stuck + confirm - 1));
        // One upright reading starts the count again.
        assertEquals(FallState.STANDING, d.update(Scenes.UPRIGHT, Vector3.ZERO, Scenes.standingFeet()));
    }

    /**
     * Our omni walk in the real server (type 0, 0.88 m/s, 10 s without a fall; recorded with
     * WALK_TRACE=1 scripts/phalanx bench walk, file in test resources): 81 single readings tilt past 50°,
     * foot impacts. None of them may read as falling, or every behaviour stops walking at once.
     */
    @Test
    void theWalksFootImpactsAreNoFall() throws Exception {
        List<String> lines = java.nio.file.Files.readAllLines(Path.of(getClass().getResource("walk-imu-type0.txt").toURI()));
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        double cos = Math.cos(Math.toRadians(LocalizationConfig.DEFAULT.fallTiltDeg()));
        int spikes = 0, n = 0;
        for (String line : lines) {
            if (line.startsWith("#")) continue;
            double[] v = java.util.Arrays.stream(line.trim().split(" ")).mapToDouble(Double::parseDouble).toArray();
            Vector3 acc = new Vector3(v[3], v[4], v[5]);
            if (acc.z() / acc.norm() < cos) spikes++;
            List<FootForce> feet = List.of(new FootForce(FootForce.Foot.LEFT, Vector3.ZERO, new Vector3(0, 0, v[6])),
                    new FootForce(FootForce.Foot.RIGHT, Vector3.ZERO, new Vector3(0, 0, v[7])));
            assertEquals(FallState.STANDING, d.update(acc, new Vector3(v[0], v[1], v[2]), feet), "walk cycle " + ++n);
        }
        assertEquals(500, n);
        assertTrue(spikes > 50, "the recording has the impact spikes: " + spikes);
    }

    @Test
    void fastRotationAloneIsAPossibleFall() {
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        assertEquals(FallState.FALLING, d.update(Scenes.UPRIGHT, new Vector3(200, 0, 0), Scenes.standingFeet()));
        assertEquals(FallState.STANDING, d.update(Scenes.UPRIGHT, Vector3.ZERO, Scenes.standingFeet()));
    }

    @Test
    void missingReadingsKeepTheState() {
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        assertEquals(FallState.STANDING, d.update(null, null, null));
        assertEquals(FallState.STANDING, d.update(new Vector3(Double.NaN, 0, 0), null, null));
        assertEquals(FallState.STANDING, d.update(Vector3.ZERO, null, List.of(new FootForce(FootForce.Foot.LEFT, Vector3.ZERO, Vector3.ZERO))));
    }

    /** S3 (needs ../shared/recordings): falls on its back at now 2.1-2.6 s and then lies still. */
    @Test
    void recordedBackFallIsDetectedAndStandingRecordingsNeverFall() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        Path s3 = Recordings.named("S3");
        List<String> lines = Recordings.perceptorMessages(s3);
        List<GroundTruth.Line> truth = GroundTruth.read(Recordings.groundTruthFile(s3));
        FallDetector d = new FallDetector(LocalizationConfig.DEFAULT);
        PerceptionParser parser = new PerceptionParser();
        int firstLying = -1, firstDetected = -1;
        for (int i = 0; i < lines.size(); i++) {
            Perception p = parser.parse(lines.get(i));
            FallState s = d.update(p.acc(), p.gyro(), p.footForces());
            GroundTruth.Line g = truth.get(i);
            boolean lying = g.hasTorso() && g.upright() < 0.2;          // torso within ~12° of horizontal
            if (lying && firstLying < 0) firstLying = i;
            if (s.isDown() && firstDetected < 0) firstDetected = i;
            if (g.hasTorso() && g.upright() > 0.95) assertFalse(s.isDown(), "line " + (i + 1) + ": upright but reported down");
            if (i > firstLying + 30 && firstLying >= 0) assertEquals(FallState.FALLEN_BACK, s, "line " + (i + 1));
        }
        assertTrue(firstLying > 0);
        assertTrue(firstDetected >= 0 && firstDetected - firstLying <= 20,
                "detected " + (firstDetected - firstLying) + " cycles after the torso lay flat");
        for (String name : new String[] {"S1", "S2", "S4_agent1", "S4_agent2", "S5_agent1", "S5_agent7", "S6"}) {
            FallDetector s = new FallDetector(LocalizationConfig.DEFAULT);
            int line = 0;
            for (String m : Recordings.perceptorMessages(Recordings.named(name))) {
                line++;
                Perception p = parser.parse(m);
                assertFalse(s.update(p.acc(), p.gyro(), p.footForces()).isDown(), name + " line " + line);
            }
        }
    }
}

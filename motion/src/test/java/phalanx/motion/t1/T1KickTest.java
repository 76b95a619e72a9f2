package phalanx.motion.t1;

import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

class T1KickTest {
    private static final T1GaitConfig G = T1GaitConfig.balanced();   // the preset the T1 player walks with
    private static final T1KickConfig K = T1KickConfig.defaults();

    /** Every cycle's commands of one whole kick, from start until the kick reports itself done (that cycle included). */
    private static List<Map<String, JointCommand>> play(T1Kick kick, boolean left, List<String> phases) {
        assertEquals(Optional.empty(), kick.start(left, true));
        List<Map<String, JointCommand>> out = new ArrayList<>();
        for (int i = 0; i < 1000 && kick.active(); i++) {
            out.add(byActuator(kick.next()));
            if (phases != null) phases.add(kick.phaseName());   // the phase this cycle's commands belong to
        }
        assertFalse(kick.active(), "the kick ends");
        return out;
    }

    private static Map<String, JointCommand> byActuator(List<JointCommand> cmds) {
        Map<String, JointCommand> m = new HashMap<>();
        for (JointCommand c : cmds) assertNull(m.put(c.actuator(), c), "one command per actuator: " + c.actuator());
        return m;
    }

    /** The joint ranges of model's t1-joints.tsv (rcsssmj robot.xml), degrees, by actuator. */
    private static Map<String, double[]> ranges() throws IOException {
        Map<String, double[]> r = new HashMap<>();
        try (var in = T1KickTest.class.getResourceAsStream("/phalanx/model/robots/t1-joints.tsv")) {
            assertNotNull(in, "t1-joints.tsv on the classpath (model module)");
            BufferedReader br = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line; (line = br.readLine()) != null; ) {
                if (line.startsWith("#") || line.isBlank()) continue;
                String[] f = line.split("\t");
                r.put(f[1], new double[]{Math.toDegrees(Double.parseDouble(f[3])), Math.toDegrees(Double.parseDouble(f[4]))});
            }
        }
        assertEquals(23, r.size());
        return r;
    }

    @Test
    void phasesPlayInOrderForTheirDurations() {
        List<String> seen = new ArrayList<>();
        List<Map<String, JointCommand>> cycles = play(new T1Kick(G, K), false, seen);
        List<String> names = new ArrayList<>(K.phases().stream().map(T1KickConfig.Phase::name).toList());
        names.add("done");
        assertEquals(names, new ArrayList<>(new LinkedHashSet<>(seen)), "each phase once, in the config's order");
        for (int i = 1; i < seen.size(); i++)
            assertTrue(names.indexOf(seen.get(i)) >= names.indexOf(seen.get(i - 1)), "no phase comes back: " + seen);
        assertEquals(K.seconds() / G.dt(), cycles.size(), 1.0, "one cycle per dt of the phases' total");
    }

    @Test
    void endsInTheGaitsStandPose() {
        T1Kick kick = new T1Kick(G, K);
        List<Map<String, JointCommand>> cycles = play(kick, false, null);
        T1Gait gait = new T1Gait(G);
        gait.feedback(0, Math.toRadians(G.torsoPitchDeg()), 0, 0);  // at the wanted attitude: no correction
        Map<String, JointCommand> stand = byActuator(gait.stand()), last = cycles.get(cycles.size() - 1);
        assertEquals(stand.keySet(), last.keySet());
        for (String a : stand.keySet()) {
            assertEquals(stand.get(a).qDeg(), last.get(a).qDeg(), 0.05, a);
            assertEquals(0, last.get(a).dqDeg(), 1e-9, a + ": no velocity once done");
        }
        assertEquals("done", kick.phaseName());
        // and after the end, the stand pose again
        Map<String, JointCommand> after = byActuator(kick.next());
        for (String a : stand.keySet()) assertEquals(stand.get(a).qDeg(), after.get(a).qDeg(), 0.05, a);
    }

    @Test
    void everyCommandStaysInTheJointRanges() throws IOException {
        Map<String, double[]> range = ranges();
        for (boolean left : new boolean[]{true, false}) {
            for (Map<String, JointCommand> cycle : play(new T1Kick(G, K), left, null)) {
                assertEquals(range.keySet(), cycle.keySet(), "all 23 actuators, each cycle");
                for (JointCommand c : cycle.values()) {
                    double[] r = range.get(c.actuator());
                    assertTrue(c.qDeg() >= r[0] - 1e-9 && c.qDeg() <= r[1] + 1e-9, c + " outside " + r[0] + ".." + r[1]);
                    assertTrue(Double.isFinite(c.dqDeg()) && c.kp() > 0 && c.kd() >= 0, c.toString());
                }
            }
        }
    }

    @Test
    void theLeftKickMirrorsTheRight() {
        List<Map<String, JointCommand>> right = play(new T1Kick(G, K), false, null), left = play(new T1Kick(G, K), true, null);
        assertEquals(right.size(), left.size());
        for (int i = 0; i < right.size(); i++) {
            for (int k = 1; k <= 6; k++) {
                double sign = k == 2 || k == 3 || k == 6 ? -1 : 1;    // roll and yaw change sign, pitches do not
                assertEquals(right.get(i).get("rle" + k).qDeg(), sign * left.get(i).get("lle" + k).qDeg(), 0.01, "cycle " + i + " joint " + k);
                assertEquals(right.get(i).get("lle" + k).qDeg(), sign * left.get(i).get("rle" + k).qDeg(), 0.01, "cycle " + i + " joint " + k);
            }
        }
    }

    @Test
    void theKickingFootSwingsForwardAndTheSupportFootStaysDown() {
        T1Kick kick = new T1Kick(G, K);
        T1LegKinematics rightLeg = new T1LegKinematics(G, false), leftLeg = new T1LegKinematics(G, true);
        List<String> phases = new ArrayList<>();
        List<Map<String, JointCommand>> cycles = play(kick, false, phases);
        double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE, maxLift = 0;
        for (int i = 0; i < cycles.size(); i++) {
            double[] kickFoot = rightLeg.footPosition(q(cycles.get(i), "rle")), support = leftLeg.footPosition(q(cycles.get(i), "lle"));
            assertEquals(G.footZ(), support[2], 0.002, "support foot on the ground, cycle " + i + " (" + phases.get(i) + ")");
            // a phase's target is reached in the first cycle of the next one
            if (phases.get(i).equals("draw") || phases.get(i).equals("swing")) minX = Math.min(minX, kickFoot[0] - support[0]);
            if (phases.get(i).equals("swing") || phases.get(i).equals("retract")) maxX = Math.max(maxX, kickFoot[0] - support[0]);
            maxLift = Math.max(maxLift, kickFoot[2] - G.footZ());
        }
        T1KickConfig.Phase draw = phase("draw"), swing = phase("swing");
        assertEquals(draw.kickX() - draw.supportX(), minX, 0.01, "drawn back");
        assertEquals(swing.kickX() - swing.supportX(), maxX, 0.01, "swung through");
        assertTrue(maxLift > 0.03, "lifted: " + maxLift);
    }

    private static T1KickConfig.Phase phase(String name) {
        return K.phases().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static double[] q(Map<String, JointCommand> cycle, String prefix) {
        double[] q = new double[6];
        for (int k = 0; k < 6; k++) q[k] = Math.toRadians(cycle.get(prefix + (k + 1)).qDeg());
        return q;
    }

    @Test
    void aKickIsRefusedWhileFallenOrKicking() {
        T1Kick kick = new T1Kick(G, K);
        Optional<String> fallen = kick.start(true, false);
        assertTrue(fallen.isPresent() && fallen.get().contains("upright"), fallen.toString());
        assertFalse(kick.active());
        assertEquals(Optional.empty(), kick.start(true, true));
        kick.next();
        Optional<String> again = kick.start(false, true);
        assertTrue(again.isPresent() && again.get().contains("already"), again.toString());
        assertTrue(kick.leftFoot(), "the running kick is unchanged");
    }

    @Test
    void aConfigMustEndInTheStandPoseAndNamesItsFields() {
        List<T1KickConfig.Phase> noEnd = K.phases().subList(0, K.phases().size() - 1);
        assertThrows(IllegalArgumentException.class, () -> new T1KickConfig(noEnd, 200, 5, 200, 2, 0.3, 0.05, 0));
        assertThrows(IllegalArgumentException.class, () -> K.with("swing.nothing", 1));
        assertThrows(IllegalArgumentException.class, () -> K.with("nophase.kickX", 1));
        assertThrows(IllegalArgumentException.class, () -> K.with("back.kickX", 0.1), "the last phase must stay the stand pose");
        assertEquals(0.25, K.with("swing.kickX", 0.25).phases().stream().filter(p -> p.name().equals("swing")).findFirst().orElseThrow().kickX());
        assertEquals(300, K.with("legKp", 300).legKp());
    }
}

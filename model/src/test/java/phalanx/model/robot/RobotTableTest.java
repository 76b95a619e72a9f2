package phalanx.model.robot;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjActions;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.comm.perception.Joint;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.*;

class RobotTableTest {

    @Test
    void aMalformedTableNamesFileAndLine() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> RobotTable.parse("x.tsv", "# a comment\n1\t2\n3\n", 2));
        assertEquals("robot table x.tsv line 3: 1 cells, 2 expected", e.getMessage());
        RobotTable t = RobotTable.parse("y.tsv", "# c\na\tb\n", 2);
        e = assertThrows(IllegalStateException.class, () -> t.number(0, 1));
        assertEquals("robot table y.tsv line 2: 'b' is not a number", e.getMessage());
        assertThrows(IllegalStateException.class, () -> RobotTable.load("none.tsv", 2));
    }

    @Test
    void theNaoTablesGiveTheRecordedStandingHeightsAndEveryJointARange() {
        // recordings README: 0.3839 m for types 0/2/4, 0.4205 for type 1, 0.4396 for type 3 (sole to torso centre)
        assertEquals(0.3839, NaoModel.ofType(0).standingTorsoHeight(), 0.002);
        assertEquals(0.4205, NaoModel.ofType(1).standingTorsoHeight(), 0.002);
        assertEquals(0.4396, NaoModel.ofType(3).standingTorsoHeight(), 0.002);
        for (Joint j : Joint.values()) assertTrue(JointLimits.maxDeg(j) > JointLimits.minDeg(j), j.name());
    }

    @Test
    void theT1TableMatchesTheActuatorsWeSendAndThePerceptorsTheServerSent() throws Exception {
        assertEquals(MjActions.T1_ACTUATORS, T1Joints.actuators());
        String line = Files.readAllLines(Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt")).get(10);
        MjPerception p = new MjPerceptionParser().parse(line);
        assertEquals(new TreeSet<>(p.joints().keySet()), new TreeSet<>(T1Joints.ALL.stream().map(T1Joints.T1Joint::perceptor).toList()));
        T1Joints.T1Joint knee = T1Joints.byActuator("lle4");
        assertEquals("Left_Knee_Pitch", knee.joint());
        assertEquals(60, knee.torque());
        assertEquals(Math.toDegrees(2.34), knee.clampDeg(200), 1e-9);
        assertNull(T1Joints.byActuator("lle7"));
    }
}

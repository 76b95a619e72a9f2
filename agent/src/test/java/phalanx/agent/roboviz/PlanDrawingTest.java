package phalanx.agent.roboviz;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Side;
import phalanx.coordination.Coordinator;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.TeamPlan;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The goalkeeper's coordination picture reaches RoboViz: one label per assignment, the on-ball one marked. */
class PlanDrawingTest {

    @Test
    void everyAssignmentIsLabelledAndTheSetIsSwapped() throws Exception {
        Vector2 ball = new Vector2(3, 1);
        List<PlayerReport> reports = new ArrayList<>();
        for (int id = 1; id <= 11; id++) reports.add(PlayerReport.complete(id, new Pose2(-12 + id * 1.5, (id % 3) * 2 - 2, 0), ball));
        TeamPlan plan = new Coordinator().coordinate(new TeamBeliefs(FieldSpec.V066, reports), Mode.ACTIVE, Memory.NONE);
        try (DatagramSocket rx = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            rx.setSoTimeout(2000);
            RoboViz rv = RoboViz.to("127.0.0.1:" + rx.getLocalPort());
            PlanDrawing.draw(rv, plan, Side.LEFT, "Phalanx");
            StringBuilder all = new StringBuilder();
            boolean swapped = false;
            while (!swapped) {
                DatagramPacket p = new DatagramPacket(new byte[4096], 4096);
                rx.receive(p);
                String text = new String(p.getData(), 0, p.getLength(), StandardCharsets.ISO_8859_1);
                all.append(text);
                swapped = p.getData()[0] == 0 || text.contains("\0\0animated.phalanx.Phalanx.plan\0");
            }
            long targets = plan.assignments().stream().filter(a -> a.target() != null).count();
            assertTrue(targets >= 10, "assignments with a target: " + targets);
            assertEquals(1, countOf(all.toString(), " ball\0"), "exactly one on-ball label");
            assertTrue(all.indexOf(plan.onBall() + " ball\0") >= 0);
            // An annotation command starts with the bytes 2, 0 (no number, colour or name here contains a 2).
            assertEquals(targets, countOf(all.toString(), "\u0002\u0000"), "one label per assignment");
        }
    }

    private static int countOf(String s, String part) {
        int n = 0;
        for (int i = s.indexOf(part); i >= 0; i = s.indexOf(part, i + 1)) n++;
        return n;
    }
}

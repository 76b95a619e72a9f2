package phalanx.bench.coordination;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import phalanx.coordination.TeamPlan;
import phalanx.bench.coordination.Scenario;
import phalanx.bench.coordination.ScenarioFile;

class SnapshotTest {
    private static TeamPlan plan(String file) throws Exception {
        Scenario s = ScenarioFile.parse(Files.readString(Path.of("bench/scenarios", file)), file);
        return Snapshot.plan(s);
    }

    @Test
    void svgIsWellFormedAndDrawsEveryPlayerArrowAndCandidate() throws Exception {
        TeamPlan plan = plan("offense.txt");
        String svg = PlanSvg.render(plan, "offense <test> & more");
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(svg.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        assertEquals("svg", doc.getDocumentElement().getNodeName());
        // 11 players + 1 ball + 1 centre circle + 9 candidates + 4 legend dots + 1 legend candidate.
        assertEquals(11 + 1 + 1 + plan.activeCandidates().size() + 5, doc.getElementsByTagName("circle").getLength());
        assertEquals(9, plan.activeCandidates().size());
        // One arrow per player that moves more than 0.3 m, plus the centre line.
        long moving = plan.assignments().stream().filter(a -> a.target() != null
                && plan.beliefs().player(a.id()).position().distanceTo(a.target()) > 0.3).count();
        assertEquals(moving + 1, doc.getElementsByTagName("line").getLength());
        assertTrue(svg.contains("offense &lt;test&gt; &amp; more"));
        assertTrue(svg.contains("on ball"));
    }

    @Test
    void defenceShowsDroppedRolesAndTheFallenPlayer() throws Exception {
        TeamPlan plan = plan("defense.txt");
        String svg = PlanSvg.render(plan, "defense");
        assertEquals(2, plan.droppedRoles().size());       // player 4 fallen, player 6 lost
        for (var r : plan.droppedRoles()) assertTrue(svg.contains(r.name() + " (dropped)"));
        assertTrue(svg.contains(">fallen<"));
        assertTrue(plan.defensive());
    }
}

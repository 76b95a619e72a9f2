package phalanx.bench.coordination;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import phalanx.coordination.Action;
import phalanx.coordination.Assignment;
import phalanx.coordination.Coordinator;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.TeamPlan;
import phalanx.bench.coordination.Scenario;
import phalanx.bench.coordination.ScenarioFile;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.support.ScramSupportMapper;

/**
 * {@code scripts/phalanx snapshot}: reads a scenario file, runs one coordination round, writes the picture as
 * SVG and prints the assignments, one line each. Usage: {@code Snapshot <scenario file> <out.svg>}.
 */
public final class Snapshot {
    private Snapshot() {}

    public static void main(String[] args) {
        if (args.length != 2) {
            System.err.println("usage: Snapshot <scenario file> <out.svg>");
            System.exit(2);
        }
        Path in = Path.of(args[0]), out = Path.of(args[1]);
        String text;
        try {
            text = Files.readString(in, StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            System.err.println("coord-snapshot: cannot read scenario " + in + ": " + e.getMessage());
            System.exit(2);
            return;
        }
        Scenario sc;
        try {
            sc = ScenarioFile.parse(text, in.toString());
        } catch (ScenarioFile.ScenarioException e) {
            System.err.println("coord-snapshot: " + e.getMessage());
            System.exit(2);
            return;
        }
        TeamPlan plan = plan(sc);
        String name = in.getFileName().toString().replaceFirst("\\.txt$", "");
        try {
            if (out.getParent() != null) Files.createDirectories(out.getParent());
            Files.writeString(out, PlanSvg.render(plan, "Phalanx coordination: " + name), StandardCharsets.UTF_8);
        } catch (IOException e) {
            System.err.println("coord-snapshot: cannot write " + out + ": " + e.getMessage());
            System.exit(2);
        }
        for (String w : plan.warnings()) System.out.println("warning: " + w);
        for (Assignment a : plan.assignments()) System.out.println(describe(a));
    }

    public static TeamPlan plan(Scenario sc) {
        Coordinator c = new Coordinator(CoordinationConfig.THESIS,
                sc.mapper().equals("scram") ? new ScramSupportMapper() : new DynamicProgrammingSupportMapper());
        return c.coordinate(sc.beliefs(), sc.mode(), sc.memory());
    }

    static String describe(Assignment a) {
        String target = a.target() == null ? "-" : String.format(java.util.Locale.ROOT, "(%.2f, %.2f) facing %.0f°",
                a.target().x(), a.target().y(), a.orientationDeg());
        return String.format("player %2d  %-10s %-16s %-3s %s", a.id(), a.subset(), a.action(),
                a.role() == null ? "-" : a.role().name(), target) + (a.action() == Action.ON_BALL ? "  <- on ball" : "");
    }
}

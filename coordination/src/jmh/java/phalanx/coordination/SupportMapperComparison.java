package phalanx.coordination;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.coordination.features.RouteCollision;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.coordination.support.ExhaustiveSupportMapper;
import phalanx.coordination.support.ScramSupportMapper;
import phalanx.coordination.support.SupportCost;
import phalanx.coordination.support.SupportMapper;
import phalanx.coordination.support.SupportMapping;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * Compares the support mappers on the same random instances and prints Markdown tables for the README:
 * Algorithm 5 (DP) against the exact optimum (gap in the thesis's cost), and DP against SCRAM (longest
 * distance, sum of distances, crossing routes, thesis cost). Two families of instances: whole rounds
 * (11 random players, the 7 support players and their formation positions, with the 3 active routes),
 * and uniform ones (8 players and 8 positions anywhere, 3 random fixed routes).
 * Run: {@code gradle -q :coordination:supportCompare} (argument: instances per family, default 1000).
 */
public final class SupportMapperComparison {
    private static final CoordinationConfig C = CoordinationConfig.THESIS;

    public static void main(String[] args) {
        int count = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        Random rnd = new Random(2012);
        List<SupportCost> rounds = new ArrayList<>(), uniform = new ArrayList<>();
        SupportCost[] captured = new SupportCost[1];
        DynamicProgrammingSupportMapper dp = new DynamicProgrammingSupportMapper();
        Coordinator capturing = new Coordinator(C, cost -> { captured[0] = cost; return dp.map(cost); });
        while (rounds.size() < count) {
            capturing.coordinate(randomTeam(rnd), Mode.ACTIVE, Memory.NONE);
            rounds.add(captured[0]);
        }
        for (int i = 0; i < count; i++) uniform.add(uniformInstance(rnd, 8));

        System.out.println("| instances | n | DP optimal | mean gap | worst gap | worst gap % |");
        System.out.println("|---|---|---|---|---|---|");
        gap("whole rounds", rounds);
        gap("uniform", uniform);
        System.out.println();
        System.out.println("| instances | mapper | longest distance (m) | sum of distances (m) | crossing pairs | likely collisions | same-time meetings | thesis cost |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (String family : new String[]{"whole rounds", "uniform"}) {
            List<SupportCost> list = family.equals("uniform") ? uniform : rounds;
            row(family, "DP (Algorithm 5)", dp, list);
            row(family, "SCRAM (MMD+MSD²)", new ScramSupportMapper(), list);
            row(family, "MSD² only", new ScramSupportMapper(false), list);
            row(family, "exhaustive optimum", new ExhaustiveSupportMapper(), list);
        }
    }

    private static void gap(String family, List<SupportCost> list) {
        DynamicProgrammingSupportMapper dp = new DynamicProgrammingSupportMapper();
        ExhaustiveSupportMapper ex = new ExhaustiveSupportMapper();
        double sum = 0, worst = 0, worstRel = 0;
        int optimal = 0;
        for (SupportCost c : list) {
            double g = dp.map(c).cost() - ex.map(c).cost();
            if (g < 1e-9) optimal++;
            sum += g;
            if (g > worst) { worst = g; }
            worstRel = Math.max(worstRel, g / Math.max(1e-9, ex.map(c).cost()));
        }
        System.out.printf(Locale.ROOT, "| %s (%d) | %d | %.1f %% | %.3f | %.2f | %.1f %% |%n", family, list.size(),
                list.get(0).size(), 100.0 * optimal / list.size(), sum / list.size(), worst, 100 * worstRel);
    }

    private static void row(String family, String name, SupportMapper m, List<SupportCost> list) {
        double longest = 0, total = 0, crossings = 0, likely = 0, meetings = 0, cost = 0;
        for (SupportCost c : list) {
            SupportMapping s = m.map(c);
            int[] p = s.positionOf();
            double l = 0;
            for (int a = 0; a < p.length; a++) {
                l = Math.max(l, c.distance(a, p[a]));
                total += c.distance(a, p[a]);
                for (int b = a + 1; b < p.length; b++) {
                    Vector2 sa = c.agent(a), ta = c.position(p[a]), sb = c.agent(b), tb = c.position(p[b]);
                    double k = RouteCollision.cost(sa.x(), sa.y(), ta.x(), ta.y(), sb.x(), sb.y(), tb.x(), tb.y(), C.collision());
                    if (k > 0) crossings++;
                    if (k == C.collision().likely()) likely++;
                    if (meet(sa, ta, sb, tb)) meetings++;
                }
            }
            longest += l;
            cost += s.cost();
        }
        int n = list.size();
        System.out.printf(Locale.ROOT, "| %s | %s | %.2f | %.2f | %.3f | %.3f | %.3f | %.2f |%n", family, name,
                longest / n, total / n, crossings / n, likely / n, meetings / n, cost / n);
    }

    /**
     * True when two players that set off together at the same speed (1 m/s; any common speed gives the
     * same answer) along their routes, each stopping at its target, come within 0.4 m of each other
     * (about two Nao shoulders): what SCRAM promises to avoid.
     */
    static boolean meet(Vector2 sa, Vector2 ta, Vector2 sb, Vector2 tb) {
        double la = sa.distanceTo(ta), lb = sb.distanceTo(tb), end = Math.max(la, lb);
        for (double t = 0; t <= end + 1e-9; t += 0.05) {
            Vector2 a = la == 0 ? sa : sa.plus(ta.minus(sa).times(Math.min(t, la) / la));
            Vector2 b = lb == 0 ? sb : sb.plus(tb.minus(sb).times(Math.min(t, lb) / lb));
            if (a.distanceTo(b) < 0.4) return true;
        }
        return false;
    }

    private static TeamBeliefs randomTeam(Random rnd) {
        Vector2 ball = point(rnd, 14, 9);
        List<PlayerReport> r = new ArrayList<>();
        r.add(PlayerReport.complete(1, new Pose2(-14.5, 0, 0), ball));
        for (int id = 2; id <= 11; id++) {
            Vector2 p = point(rnd, 15, 10);
            r.add(PlayerReport.complete(id, new Pose2(p.x(), p.y(), 0), ball));
        }
        return new TeamBeliefs(FieldSpec.V066, r);
    }

    private static SupportCost uniformInstance(Random rnd, int n) {
        List<Vector2> a = new ArrayList<>(), p = new ArrayList<>(), fs = new ArrayList<>(), ft = new ArrayList<>();
        for (int i = 0; i < n; i++) { a.add(point(rnd, 15, 10)); p.add(point(rnd, 14.5, 9.5)); }
        for (int i = 0; i < 3; i++) { fs.add(point(rnd, 15, 10)); ft.add(point(rnd, 15, 10)); }
        return new SupportCost(a, p, fs, ft, C.supportWeights(), C.collision());
    }

    private static Vector2 point(Random rnd, double hx, double hy) {
        return new Vector2((rnd.nextDouble() * 2 - 1) * hx, (rnd.nextDouble() * 2 - 1) * hy);
    }
}

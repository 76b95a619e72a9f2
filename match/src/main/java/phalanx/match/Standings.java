package phalanx.match;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The thesis's two result tables (6.5) from a list of games: per opponent W, D, L, average goal
 * difference and games (Table 6.4), and a league table P, W, D, L, F, A, Pts with 3/1/0 points
 * (Table 6.5). Only completed games count; the others are listed by how many and why.
 */
public final class Standings {
    private Standings() { }

    /** A game between two teams by their labels; {@code counted} false for a game that did not finish. */
    public record Game(String left, String right, int scoreLeft, int scoreRight, boolean counted, String note) {
        public static Game of(MatchResult r) {
            String note = r.completed() ? "" : r.reason();
            for (MatchResult.TeamResult t : List.of(r.left(), r.right())) {
                if (!t.status().equals("ok")) note += (note.isEmpty() ? "" : "; ") + t.label() + " " + t.status();
            }
            return new Game(r.left().label(), r.right().label(), r.left().score(), r.right().score(), r.completed(), note);
        }

        boolean involves(String team) { return left.equals(team) || right.equals(team); }

        /** Goals for minus goals against, seen from {@code team}. */
        int difference(String team) { return left.equals(team) ? scoreLeft - scoreRight : scoreRight - scoreLeft; }

        String opponentOf(String team) { return left.equals(team) ? right : left; }
    }

    /** Table 6.4: one row per opponent of {@code us}. {@code differences} are the counted games' goal differences. */
    public record OpponentRow(String opponent, int won, int drawn, int lost, double averageDifference,
                              double spread, int games, int notCounted, List<Integer> differences) { }

    /** Table 6.5: one row per team. */
    public record LeagueRow(String team, int played, int won, int drawn, int lost, int goalsFor, int goalsAgainst, int points) { }

    public static List<OpponentRow> versus(String us, List<Game> games) {
        Map<String, List<Game>> byOpponent = new LinkedHashMap<>();
        for (Game g : games) if (g.involves(us)) byOpponent.computeIfAbsent(g.opponentOf(us), k -> new ArrayList<>()).add(g);
        List<OpponentRow> rows = new ArrayList<>();
        byOpponent.forEach((opp, list) -> {
            int w = 0, d = 0, l = 0, nc = 0;
            List<Integer> diffs = new ArrayList<>();
            for (Game g : list) {
                if (!g.counted()) {
                    nc++;
                    continue;
                }
                int diff = g.difference(us);
                diffs.add(diff);
                if (diff > 0) w++;
                else if (diff == 0) d++;
                else l++;
            }
            double mean = diffs.stream().mapToInt(Integer::intValue).average().orElse(Double.NaN);
            double var = diffs.size() < 2 ? 0 : diffs.stream().mapToDouble(x -> (x - mean) * (x - mean)).sum() / (diffs.size() - 1);
            rows.add(new OpponentRow(opp, w, d, l, mean, Math.sqrt(var), diffs.size(), nc, List.copyOf(diffs)));
        });
        return rows;
    }

    /** The league table, best first: points, then goal difference, then goals scored, then name. */
    public static List<LeagueRow> league(List<Game> games) {
        Map<String, int[]> t = new LinkedHashMap<>(); // P W D L F A
        for (Game g : games) {
            t.computeIfAbsent(g.left(), k -> new int[6]);
            t.computeIfAbsent(g.right(), k -> new int[6]);
            if (!g.counted()) continue;
            add(t.get(g.left()), g.scoreLeft(), g.scoreRight());
            add(t.get(g.right()), g.scoreRight(), g.scoreLeft());
        }
        List<LeagueRow> rows = new ArrayList<>();
        t.forEach((team, v) -> rows.add(new LeagueRow(team, v[0], v[1], v[2], v[3], v[4], v[5], 3 * v[1] + v[2])));
        rows.sort(Comparator.comparingInt(LeagueRow::points).reversed()
                .thenComparing(Comparator.comparingInt((LeagueRow r) -> r.goalsFor() - r.goalsAgainst()).reversed())
                .thenComparing(Comparator.comparingInt(LeagueRow::goalsFor).reversed())
                .thenComparing(LeagueRow::team));
        return rows;
    }

    private static void add(int[] v, int f, int a) {
        v[0]++;
        if (f > a) v[1]++;
        else if (f == a) v[2]++;
        else v[3]++;
        v[4] += f;
        v[5] += a;
    }

    public static String table64(String us, List<OpponentRow> rows) {
        StringBuilder sb = new StringBuilder();
        sb.append("| ").append(us).append(" against | W | D | L | avg goal diff (± sd) | games | not completed |\n");
        sb.append("|---|---:|---:|---:|---:|---:|---:|\n");
        for (OpponentRow r : rows) {
            String avg = r.games() == 0 ? "-" : String.format(Locale.ROOT, "%+.2f (± %.2f)", r.averageDifference(), r.spread());
            sb.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %s | %d | %d |%n", r.opponent(), r.won(), r.drawn(),
                    r.lost(), avg, r.games(), r.notCounted()));
        }
        return sb.toString();
    }

    public static String table65(List<LeagueRow> rows) {
        StringBuilder sb = new StringBuilder();
        sb.append("| # | team | P | W | D | L | F | A | Pts |\n|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
        int i = 1;
        for (LeagueRow r : rows) {
            sb.append(String.format(Locale.ROOT, "| %d | %s | %d | %d | %d | %d | %d | %d | %d |%n", i++, r.team(), r.played(),
                    r.won(), r.drawn(), r.lost(), r.goalsFor(), r.goalsAgainst(), r.points()));
        }
        return sb.toString();
    }
}

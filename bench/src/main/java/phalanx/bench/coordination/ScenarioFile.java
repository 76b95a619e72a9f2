package phalanx.bench.coordination;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.ReportType;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * A plain-text coordination input, to reproduce and picture a situation (scripts/phalanx snapshot).
 * One directive per line, {@code #} starts a comment, coordinates in metres in the team's own frame
 * (own goal at -x), angles in degrees:
 * <pre>
 * field 11                      # 11 (30 x 20 m, default) or 9 (21 x 14 m)
 * mode active                   # active (default), support or wait
 * mapper dp                     # dp (Algorithm 5, default) or scram
 * previous 7 [bx by]            # previous on-ball player, optionally the previous ball
 * ball bx by                    # the coordinator's own ball, used only if nobody reports one
 * C id x y theta bx by [fallen] # complete: pose and ball
 * L id x y theta [fallen]       # pose only
 * B id distance bearing [heading] [fallen]
 * X id                          # lost
 * </pre>
 */
public final class ScenarioFile {
    private ScenarioFile() {}

    /** Thrown for a line that cannot be read; the message names the file and the line. */
    public static final class ScenarioException extends Exception {
        public ScenarioException(String message) { super(message); }
    }

    public static Scenario parse(String text, String name) throws ScenarioException {
        FieldSpec field = FieldSpec.V066;
        Mode mode = Mode.ACTIVE;
        String mapper = "dp";
        Memory memory = Memory.NONE;
        Vector2 fallback = null;
        List<PlayerReport> reports = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i];
            int hash = line.indexOf('#');
            if (hash >= 0) line = line.substring(0, hash);
            String[] t = line.trim().split("\\s+");
            if (t.length == 0 || t[0].isEmpty()) continue;
            Line l = new Line(name, i + 1, t);
            switch (t[0]) {
                case "field" -> {
                    l.count(2, 2);
                    int players = l.integer(1);
                    if (players != 9 && players != 11) throw l.error("field must be 9 or 11 players, got " + players);
                    field = FieldSpec.forPlayers(players);
                }
                case "mode" -> {
                    l.count(2, 2);
                    try {
                        mode = Mode.valueOf(t[1].toUpperCase(Locale.ROOT));
                    } catch (IllegalArgumentException e) {
                        throw l.error("mode must be active, support or wait, got '" + t[1] + "'");
                    }
                }
                case "mapper" -> {
                    l.count(2, 2);
                    if (!t[1].equals("dp") && !t[1].equals("scram")) throw l.error("mapper must be dp or scram, got '" + t[1] + "'");
                    mapper = t[1];
                }
                case "previous" -> {
                    l.count(2, 4);
                    if (t.length == 3) throw l.error("previous takes an id, or an id and the ball's x and y");
                    memory = new Memory(l.integer(1), t.length == 4 ? new Vector2(l.number(2), l.number(3)) : null);
                }
                case "ball" -> {
                    l.count(3, 3);
                    fallback = new Vector2(l.number(1), l.number(2));
                }
                case "C" -> {
                    boolean fallen = l.fallen(7);
                    PlayerReport r = PlayerReport.complete(l.integer(1), new Pose2(l.number(2), l.number(3), l.number(4)),
                            new Vector2(l.number(5), l.number(6)));
                    reports.add(fallen ? r.asFallen() : r);
                }
                case "L" -> {
                    boolean fallen = l.fallen(5);
                    PlayerReport r = PlayerReport.located(l.integer(1), new Pose2(l.number(2), l.number(3), l.number(4)));
                    reports.add(fallen ? r.asFallen() : r);
                }
                case "B" -> {
                    boolean fallen = t[t.length - 1].equals("fallen");
                    int n = fallen ? t.length - 1 : t.length;
                    if (n != 4 && n != 5) throw l.error("B takes: id distance bearing [heading] [fallen]");
                    PlayerReport r = PlayerReport.ballOnly(l.integer(1), l.number(2), l.number(3), n == 5 ? l.number(4) : Double.NaN);
                    reports.add(fallen ? r.asFallen() : r);
                }
                case "X" -> {
                    boolean fallen = l.fallen(2);
                    PlayerReport r = PlayerReport.lost(l.integer(1));
                    reports.add(fallen ? r.asFallen() : r);
                }
                default -> throw l.error("unknown directive '" + t[0] + "' (field, mode, mapper, previous, ball, "
                        + String.join(", ", names()) + ")");
            }
        }
        if (reports.isEmpty()) throw new ScenarioException(name + ": no player report (C, L, B or X lines)");
        return new Scenario(name, new TeamBeliefs(field, reports, fallback), mode, memory, mapper);
    }

    private static List<String> names() {
        List<String> n = new ArrayList<>();
        for (ReportType r : ReportType.values()) n.add(r.name());
        return n;
    }

    private record Line(String file, int number, String[] t) {
        ScenarioException error(String message) { return new ScenarioException(file + ":" + number + ": " + message); }

        void count(int min, int max) throws ScenarioException {
            int args = t.length - 1;
            if (t.length < min || t.length > max)
                throw error(t[0] + " takes " + (min == max ? String.valueOf(min - 1) : (min - 1) + " to " + (max - 1))
                        + " values, got " + args);
        }

        /** Checks the count for a report with an optional trailing "fallen"; returns whether it is there. */
        boolean fallen(int fields) throws ScenarioException {
            boolean fallen = t.length == fields + 1 && t[fields].equals("fallen");
            if (t.length != fields && !fallen)
                throw error(t[0] + " takes " + (fields - 1) + " values and an optional 'fallen', got: " + String.join(" ", t));
            return fallen;
        }

        double number(int i) throws ScenarioException {
            try {
                double v = Double.parseDouble(t[i]);
                if (!Double.isFinite(v)) throw error("value " + i + " of " + t[0] + " is not finite: '" + t[i] + "'");
                return v;
            } catch (NumberFormatException e) {
                throw error("value " + i + " of " + t[0] + " is not a number: '" + t[i] + "'");
            }
        }

        int integer(int i) throws ScenarioException {
            try {
                return Integer.parseInt(t[i]);
            } catch (NumberFormatException e) {
                throw error("value " + i + " of " + t[0] + " is not a whole number: '" + t[i] + "'");
            }
        }
    }
}

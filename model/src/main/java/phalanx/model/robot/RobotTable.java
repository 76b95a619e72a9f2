package phalanx.model.robot;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads one robot description table from the classpath (resources phalanx/model/robots/, README there):
 * tab-separated rows, {@code #} comment lines. A malformed table fails at once, naming file and line.
 */
final class RobotTable {
    private final String name;
    private final List<String[]> rows;
    private final List<Integer> lines;

    private RobotTable(String name, List<String[]> rows, List<Integer> lines) {
        this.name = name;
        this.rows = rows;
        this.lines = lines;
    }

    /** Loads {@code phalanx/model/robots/NAME}, every row with exactly {@code columns} cells. */
    static RobotTable load(String name, int columns) {
        try (InputStream in = RobotTable.class.getResourceAsStream("/phalanx/model/robots/" + name)) {
            if (in == null) throw new IllegalStateException("robot table " + name + " is missing from the classpath");
            return parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8), columns);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read robot table " + name + ": " + e.getMessage(), e);
        }
    }

    static RobotTable parse(String name, String text, int columns) {
        List<String[]> rows = new ArrayList<>();
        List<Integer> lines = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new java.io.StringReader(text))) {
            String line;
            int n = 0;
            while ((line = r.readLine()) != null) {
                n++;
                if (line.isBlank() || line.startsWith("#")) continue;
                String[] cells = line.split("\t", -1);
                if (cells.length != columns) {
                    throw new IllegalStateException("robot table " + name + " line " + n + ": " + cells.length
                            + " cells, " + columns + " expected");
                }
                rows.add(cells);
                lines.add(n);
            }
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        return new RobotTable(name, rows, lines);
    }

    int size() { return rows.size(); }

    String text(int row, int column) { return rows.get(row)[column]; }

    double number(int row, int column) {
        String v = rows.get(row)[column];
        try {
            double d = Double.parseDouble(v);
            if (Double.isFinite(d)) return d;
        } catch (NumberFormatException e) {
            // named below
        }
        throw new IllegalStateException("robot table " + name + " line " + lines.get(row) + ": '" + v + "' is not a number");
    }
}

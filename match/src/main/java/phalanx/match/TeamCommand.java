package phalanx.match;

import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A team's start command with placeholders: {@code {host}} and {@code {port}} (the server's agent
 * port; required, or the team would join whatever server runs on 3100) and {@code {dir}} (a folder
 * for the team's logs). For example {@code scripts/start.sh {host} {port} Phalanx --log-dir {dir}} or
 * {@code cd /opt/teams/utaustinvilla3d && ./start.sh {host} -p {port}}.
 */
public record TeamCommand(String label, String template) {
    private static final Pattern PLACEHOLDER = Pattern.compile("\\{([A-Za-z]*)}");
    private static final Pattern LABEL = Pattern.compile("[A-Za-z0-9_.-]{1,40}");

    /** Checks the template; a bad one fails with a message that says what is wrong. */
    public TeamCommand {
        if (label == null || !LABEL.matcher(label).matches()) {
            throw new IllegalArgumentException("team name '" + label + "' must be 1-40 letters, digits, '_', '.' or '-'");
        }
        if (template == null || template.isBlank()) {
            throw new IllegalArgumentException("team " + label + ": the start command is empty");
        }
        Matcher m = PLACEHOLDER.matcher(template);
        boolean port = false;
        while (m.find()) {
            switch (m.group(1)) {
                case "host", "dir" -> { }
                case "port" -> port = true;
                default -> throw new IllegalArgumentException("team " + label + ": unknown placeholder {" + m.group(1)
                        + "} in '" + template + "' (known: {host} {port} {dir})");
            }
        }
        if (!port) {
            throw new IllegalArgumentException("team " + label + ": the start command has no {port} placeholder, so its "
                    + "players would not find this match's server: '" + template + "'");
        }
    }

    /** Parses {@code NAME=COMMAND} (the tournament's --team argument). */
    public static TeamCommand parse(String spec) {
        int eq = spec.indexOf('=');
        if (eq <= 0) throw new IllegalArgumentException("--team wants NAME=COMMAND, got '" + spec + "'");
        return new TeamCommand(spec.substring(0, eq).trim(), spec.substring(eq + 1));
    }

    /** The shell command for this server and log folder. */
    public String expand(String host, int port, String dir) {
        Map<String, String> v = Map.of("host", host, "port", Integer.toString(port), "dir", dir);
        Matcher m = PLACEHOLDER.matcher(template);
        StringBuilder sb = new StringBuilder();
        while (m.find()) m.appendReplacement(sb, Matcher.quoteReplacement(v.get(m.group(1))));
        m.appendTail(sb);
        return sb.toString();
    }
}

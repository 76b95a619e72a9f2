package phalanx.match;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * What {@code scripts/phalanx match} writes at the end of a game (one JSON file): the score, the goals with
 * their game time, the play-mode timeline, each team's players that never connected or disconnected,
 * and how the processes ended. {@code completed} is true only when the server reached GameOver.
 * {@code playWallSeconds}: wall time from the first kick-off to the end; against {@code gameTime} it
 * says whether the machine kept real time (in agent-sync mode the game slows down instead of dropping cycles).
 */
public record MatchResult(boolean completed, String reason, String started, double wallSeconds, Double playWallSeconds,
                          ServerInfo server, double halfTime, int halves, double gameTime,
                          TeamResult left, TeamResult right, List<Goal> goals,
                          List<ModeChange> playModes, List<RosterEvent> rosterEvents) {

    /** A goal: game time, half, the scoring side and team, and the score after it. */
    public record Goal(double time, int half, String side, String team, int scoreLeft, int scoreRight) { }

    /** The play mode became {@code mode} at this game time. */
    public record ModeChange(double time, int half, String mode) { }

    /** A robot appeared on ({@code joined}) or vanished from the field. */
    public record RosterEvent(double time, int half, String side, int unum, boolean joined) { }

    public record ServerInfo(int agentPort, int monitorPort, boolean sync, boolean realTime, String log,
                             Integer exitCode, boolean diedDuringGame) { }

    /**
     * One team. {@code label} is the name the match was asked to play under, {@code team} the name
     * its players gave the server. {@code status}: ok, incomplete (some players missing or
     * disconnected), crashed (had players, none left at the end), never-connected, failed-to-start
     * (its start command exited with an error and no player ever connected), or not-started.
     */
    public record TeamResult(String label, String team, String command, String side, int score, String status,
                             Integer startExitCode, List<Integer> connected, List<Integer> neverConnected,
                             List<Integer> disconnected, Double processesGoneAt, String log) {

        /** The status from the facts, see the record's comment. */
        public static String status(int everConnected, int presentAtEnd, int neverConnected, int disconnected,
                                    Integer startExitCode) {
            if (everConnected == 0) {
                return startExitCode != null && startExitCode != 0 ? "failed-to-start" : "never-connected";
            }
            if (presentAtEnd == 0) return "crashed";
            if (neverConnected > 0 || disconnected > 0) return "incomplete";
            return "ok";
        }
    }

    private static final ObjectMapper JSON = new ObjectMapper()
            .enable(SerializationFeature.INDENT_OUTPUT)
            .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);

    public String toJson() {
        try {
            return JSON.writeValueAsString(this);
        } catch (IOException e) {
            throw new IllegalStateException("cannot write a match result as JSON: " + e.getMessage(), e);
        }
    }

    public void write(Path file) throws IOException {
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.writeString(tmp, toJson() + "\n");
        Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    /** Reads a result file; a file that is not a match result fails with a message naming it. */
    public static MatchResult read(Path file) throws IOException {
        try {
            MatchResult r = JSON.readValue(file.toFile(), MatchResult.class);
            if (r.left() == null || r.right() == null) throw new IOException("no left or right team");
            return r;
        } catch (IOException e) {
            throw new IOException(file + " is not a match result: " + e.getMessage().lines().findFirst().orElse(""), e);
        }
    }
}

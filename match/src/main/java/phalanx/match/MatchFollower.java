package phalanx.match;

import phalanx.comm.monitor.MatchState;
import phalanx.comm.monitor.MonitorHeader;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.match.MatchResult.Goal;
import phalanx.match.MatchResult.ModeChange;
import phalanx.match.MatchResult.RosterEvent;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SortedSet;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Follows a game on the monitor stream: folds each message into the score, the goals with their game
 * time, the play-mode timeline and the robots present on each side. Values in, values out: it never
 * touches a socket or the clock, so a recorded stream gives the same result as a live one.
 * Thread-safe (the referee reads it while a reader thread feeds it).
 */
public final class MatchFollower {
    private static final Pattern HALF_TIME = Pattern.compile("\\(RuleHalfTime ([0-9.eE+-]+)\\)");

    private final MonitorHeader header = new MonitorHeader();
    private MatchState state = MatchState.INITIAL;
    private double halfTime = 300; // the server's default (naosoccersim.rb) until the stream says otherwise
    private long messages;
    private final List<ModeChange> timeline = new ArrayList<>();
    private final List<Goal> goals = new ArrayList<>();
    private final List<RosterEvent> rosterEvents = new ArrayList<>();
    private final Map<Side, SortedSet<Integer>> present = new EnumMap<>(Side.class);
    private final Map<Side, SortedSet<Integer>> everSeen = new EnumMap<>(Side.class);
    private final Map<Side, String> teamNames = new EnumMap<>(Side.class);

    public MatchFollower() {
        for (Side s : Side.values()) {
            present.put(s, new TreeSet<>());
            everSeen.put(s, new TreeSet<>());
        }
    }

    /** Folds one monitor message in. Messages that are not monitor messages change nothing. */
    public synchronized void accept(String message) {
        MatchState before = state;
        state = header.apply(before, message);
        if (messages++ == 0 || state.playMode() != before.playMode() || state.half() != before.half()) {
            timeline.add(new ModeChange(state.time(), state.half(), state.playMode().wireName()));
        }
        if (state.teamLeft() != null) teamNames.put(Side.LEFT, state.teamLeft());
        if (state.teamRight() != null) teamNames.put(Side.RIGHT, state.teamRight());
        for (int n = before.scoreLeft() + 1; n <= state.scoreLeft(); n++) goal(Side.LEFT, n, state.scoreRight());
        for (int n = before.scoreRight() + 1; n <= state.scoreRight(); n++) goal(Side.RIGHT, state.scoreLeft(), n);
        Matcher h = HALF_TIME.matcher(message);
        h.region(0, sceneStart(message));
        if (h.find()) {
            try {
                halfTime = Double.parseDouble(h.group(1));
            } catch (NumberFormatException ignored) {
                // keep the last known half time
            }
        }
        Optional<SortedSet<SceneRoster.Robot>> robots = SceneRoster.of(message);
        robots.ifPresent(this::roster);
    }

    /** Where the scene part ({@code (RSG …)} or {@code (RDS …)}) starts: the header is before it. */
    private static int sceneStart(String message) {
        int rsg = message.indexOf("(RSG ");
        int rds = message.indexOf("(RDS ");
        if (rsg < 0) return rds < 0 ? message.length() : rds;
        return rds < 0 ? rsg : Math.min(rsg, rds);
    }

    private void goal(Side side, int left, int right) {
        goals.add(new Goal(state.time(), state.half(), side.name().toLowerCase(), teamNames.get(side), left, right));
    }

    private void roster(SortedSet<SceneRoster.Robot> robots) {
        for (Side side : Side.values()) {
            SortedSet<Integer> now = new TreeSet<>();
            for (SceneRoster.Robot r : robots) if (r.side() == side) now.add(r.unum());
            SortedSet<Integer> was = present.get(side);
            for (int u : now) if (!was.contains(u)) rosterEvents.add(new RosterEvent(state.time(), state.half(), side.name().toLowerCase(), u, true));
            for (int u : was) if (!now.contains(u)) rosterEvents.add(new RosterEvent(state.time(), state.half(), side.name().toLowerCase(), u, false));
            present.put(side, now);
            everSeen.get(side).addAll(now);
        }
    }

    public synchronized MatchState state() { return state; }
    public synchronized double halfTime() { return halfTime; }
    public synchronized long messages() { return messages; }
    public synchronized boolean gameOver() { return state.playMode() == PlayMode.GAME_OVER; }
    public synchronized String teamName(Side side) { return teamNames.get(side); }
    public synchronized SortedSet<Integer> present(Side side) { return new TreeSet<>(present.get(side)); }
    public synchronized SortedSet<Integer> everSeen(Side side) { return new TreeSet<>(everSeen.get(side)); }
    public synchronized int presentCount() { return present.get(Side.LEFT).size() + present.get(Side.RIGHT).size(); }
    public synchronized List<ModeChange> timeline() { return List.copyOf(timeline); }
    public synchronized List<Goal> goals() { return List.copyOf(goals); }
    public synchronized List<RosterEvent> rosterEvents() { return List.copyOf(rosterEvents); }

    /** Uniform numbers 1..expected that were never on the field for this side. */
    public synchronized List<Integer> neverConnected(Side side, int expected) {
        List<Integer> missing = new ArrayList<>();
        for (int u = 1; u <= expected; u++) if (!everSeen.get(side).contains(u)) missing.add(u);
        return missing;
    }

    /** Players that were on the field and are gone now. */
    public synchronized List<Integer> disconnected(Side side) {
        List<Integer> gone = new ArrayList<>();
        for (int u : everSeen.get(side)) if (!present.get(side).contains(u)) gone.add(u);
        return gone;
    }
}

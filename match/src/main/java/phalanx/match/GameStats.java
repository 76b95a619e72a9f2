package phalanx.match;

import phalanx.comm.monitor.MatchState;
import phalanx.comm.monitor.MonitorHeader;
import phalanx.comm.monitor.MonitorScene;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.zip.GZIPInputStream;

/**
 * What happened in a game, per team, from its monitor log (one monitor message a line, as the match
 * runner records it in {@code monitor.log.gz}): goals, kicks and how far they went, shots on goal,
 * possession, where the ball was, falls and time lying, robots the referee moved, set pieces.
 * A pure fold over the messages; every definition is in the field comments below (docs/matches.md).
 */
public final class GameStats {
    /** A torso more than 60 degrees from upright is lying (as scripts/phalanx watch marks it). */
    static final double LYING_UP_Z = 0.5;
    /** The ball leaves from rest: below this speed before, m/s ... */
    static final double REST_SPEED = 0.5;
    /** ... and above this after (a walking push stays below it). */
    static final double KICK_SPEED = 1.2;
    /** A kick ends when the ball is back below this speed. */
    static final double STOP_SPEED = 0.3;
    /** Faster than any kick (~10 m/s at most): the trainer or the referee put the ball somewhere. */
    static final double TELEPORT_SPEED = 15;
    /** A torso that moves this far between two pictures 0.1 s or less apart was moved by the referee. */
    static final double RELOCATION_M = 1.0;
    /** The kicker is the nearest torso, if it is this close to the ball. */
    static final double KICKER_RANGE = 1.0;
    static final double FIELD_HALF_LENGTH = 15, GOAL_HALF_WIDTH = 1.05, THIRD_X = 5;
    /** A shot on goal ends in the goal or within this of the goal line, having been aimed between the posts. */
    static final double SHOT_END_M = 2.0;
    /** A free kick for the other side this soon after a kick-off turned into PlayOn is the taker's second touch. */
    static final double KICK_OFF_FOUL_S = 1.0;
    /** A goal's shot is a kick that started at most this long before it (a 10 m roll at the slowest kick's speed). */
    static final double GOAL_SHOT_S = 10.0;
    /**
     * A torso this high is held up by the referee for a foul: SoccerRuleAspect::ClearPlayersAutomatic lifts the
     * offender to 1.0 m and more for FoulHoldTime (0.5 s) before it moves him off the field (docs/protocol.md,
     * "Charging and crowding"); a standing Nao's torso is at about 0.4 m.
     */
    static final double HELD_Z = 0.9;
    /** The penalty area, from the goal line (naosoccersim.rb PenaltyLength 1.8, PenaltyWidth 3.9). */
    static final double PENALTY_LENGTH = 1.8, PENALTY_HALF_WIDTH = 1.95;
    /** More field players than this inside their own penalty area is illegal defence (MaxPlayersInsideOwnArea). */
    static final int MAX_IN_OWN_AREA = 3;

    /** One team's figures. Times in seconds of game time. */
    public static final class TeamStats {
        public String name;
        public int goals, kicks, kicksOver8m, kicksUnder1_5m, shotsOnGoal, falls, relocated;
        /** Fouls the referee took a player off for, by kind (see {@link Foul}). */
        public final Map<Foul.Kind, Integer> fouls = new EnumMap<>(Foul.Kind.class);
        /** The server's self-collision records (a robot's own limbs touching: its joints freeze, it is not moved). */
        public int selfCollisions;

        public int fouls(Foul.Kind k) { return fouls.getOrDefault(k, 0); }
        /** This team's kick-offs, and those of them the other side got a free kick from (docs/protocol.md, "Set pieces"). */
        public int kickOffs, kickOffFouls;
        public double possessionS, ownThirdS, middleS, opponentThirdS, lyingS;
        /** Contests (see {@link GameStats#contests()}) this team moved the ball out of first. */
        public int contestsWon;
        /** Set pieces awarded to this team, by play mode (free kicks count the other side's fouls). */
        public final Map<String, Integer> setPieces = new HashMap<>();

        int setPiece(String kind) { return setPieces.getOrDefault(kind, 0); }
    }

    private final MonitorScene scene = new MonitorScene();
    private final MonitorHeader header = new MonitorHeader();
    private final Map<Side, TeamStats> teams = new EnumMap<>(Side.class);
    private final int players;
    private MatchState state = MatchState.INITIAL;
    private double lastTime = Double.NaN;
    private double[] lastBall;
    private double lastBallSpeed;
    private final double[][][] lastTorso = new double[2][12][];   // side, unum: {x, y, upZ}
    private Kick kick;                                            // the kick in flight, or null
    private PlayMode lastMode = PlayMode.BEFORE_KICK_OFF;
    private Side kickOffTeam;                                     // whose kick-off the current PlayOn came from
    private double kickOffPlayOnAt = Double.NaN;
    private double playOnS;
    private long messages, unreadable;
    private double contestStart = Double.NaN;                     // the contest going on since, or NaN
    private boolean contestOpen;                                  // the last contest ended and nobody kicked since
    private int contests;
    private double contestS;
    final double[][] ballCells = new double[30][20];              // PlayOn seconds per 1 m cell, for the heat map

    private record Kick(Side team, double t0, double x0, double y0, double dx, double dy, Defence defence) {}

    /** One kick as counted: game time, team, from and to (field frame), length; the other side as it stood when it left. */
    public record KickEvent(double time, Side team, double x0, double y0, double x1, double y1, double length, boolean onGoal,
                            Defence defence) {}

    /**
     * The defending side at one moment: its player 1 (the keeper; null when not on the field) as {x, y, upZ},
     * and its torso nearest the ball, metres.
     */
    public record Defence(double[] keeper, double nearest) {
        public boolean keeperLying() { return keeper != null && keeper[2] < LYING_UP_Z; }
    }

    /**
     * A goal: game time, the scoring side, its shot (the last kick of the scorer that ended at the goal, null when
     * the ball was walked in) and the defence when the ball went in.
     */
    public record Goal(double time, Side scorer, KickEvent shot, Defence atGoal) {}

    /**
     * A player the referee held up for a foul: when, who, where he stood the picture before, the ball's distance, and the
     * nearest opponent (distance, and whether that one was nearer the ball). The kind is the server's when its monitor
     * stream names the foul (SoccerRuleItem's {@code (foul index type team unum)}, sent by the SimSpark-SPL snapshot);
     * else it is read off the picture before: lying = incapable (on the ground 15 s or not standing 30 s), one of more
     * than three of his team's field players in his own penalty area = illegal defence, else contact.
     */
    public record Foul(double time, Side side, int unum, double x, double y, Kind kind, double ballDistance,
                       double nearestOpponent, boolean opponentNearerBall) {
        /** SoccerRuleAspect::EFoulType in its order (the monitor's number), then CONTACT for a foul the server did not name. */
        public enum Kind {
            CROWDING, TOUCHING, ILLEGAL_DEFENCE, ILLEGAL_ATTACK, INCAPABLE, KICK_OFF, CHARGING, SELF_COLLISION, CONTACT;

            static Kind ofServer(int type) { return type >= 0 && type < CONTACT.ordinal() ? values()[type] : null; }

            String key() { return name().toLowerCase(Locale.ROOT); }
        }
    }

    /** The kind and game time of each player's last foul as the server named it, side then unum; null: none. */
    private final Foul.Kind[][] namedKind = new Foul.Kind[2][12];
    private final double[][] namedAt = new double[2][12];
    /** A foul the server named this long before the player was held up is the one he is held for. */
    static final double NAMED_WITHIN_S = 1.0;
    /** A contest: in PlayOn the ball under this speed (m/s) ... */
    static final double CONTEST_STILL_SPEED = 0.1;
    /** ... with an upright player of each team within this of it (m) ... */
    static final double CONTEST_RANGE = 1.0;
    /** ... for at least this long (s). Its winner is the team that kicks the ball next, before the play mode changes. */
    static final double CONTEST_MIN_S = 1.0;

    private final java.util.List<Foul> foulEvents = new java.util.ArrayList<>();
    private final double[][] lastZ = new double[2][12];

    /** Every foul counted, in order. */
    public java.util.List<Foul> fouls() { return java.util.List.copyOf(foulEvents); }

    private final java.util.List<KickEvent> kickEvents = new java.util.ArrayList<>();
    private final java.util.List<Goal> goalEvents = new java.util.ArrayList<>();

    /** Every kick counted, in order. */
    public java.util.List<KickEvent> kicks() { return java.util.List.copyOf(kickEvents); }

    /** Every goal, in order. */
    public java.util.List<Goal> goals() { return java.util.List.copyOf(goalEvents); }

    public GameStats(int players) {
        this.players = players;
        for (Side s : Side.values()) teams.put(s, new TeamStats());
    }

    public TeamStats team(Side side) { return teams.get(side); }
    public double playOnSeconds() { return playOnS; }

    /**
     * Still balls fought over: in PlayOn the ball (nearly) still for at least CONTEST_MIN_S with an upright player of
     * each team within CONTEST_RANGE of it (issue 18: against UT Austin Villa a third of the game goes so). Each
     * team's {@link TeamStats#contestsWon} counts those it moved the ball out of with the next kick.
     */
    public int contests() { return contests; }

    /** Game seconds the ball lay in such contests. */
    public double contestSeconds() { return contestS; }
    public long messages() { return messages; }
    public long unreadable() { return unreadable; }
    public MatchState state() { return state; }

    /** Folds one monitor message in; one the scene reader cannot read is counted and skipped. */
    public void accept(String message) {
        messages++;
        state = header.apply(state, message);
        try {
            scene.apply(message);
        } catch (IllegalArgumentException e) {
            unreadable++;
            return;
        }
        if (state.teamLeft() != null) teams.get(Side.LEFT).name = state.teamLeft();
        if (state.teamRight() != null) teams.get(Side.RIGHT).name = state.teamRight();
        PlayMode mode = state.playMode();
        double t = state.time();
        namedFouls(message, t);
        if (mode != lastMode) modeChanged(mode, t);
        scored(Side.LEFT, state.scoreLeft(), t);
        scored(Side.RIGHT, state.scoreRight(), t);
        double[] ball = scene.ball();
        if (!scene.hasScene() || ball == null || !Double.isFinite(t)) return;
        double dt = Double.isFinite(lastTime) ? t - lastTime : 0;
        if (dt > 0 && dt <= 1) step(mode, dt, ball);
        if (dt != 0 || !Double.isFinite(lastTime)) {
            lastTime = t;
            lastBall = ball;
        }
    }

    private void modeChanged(PlayMode mode, double t) {
        endKick(lastBall);
        PlayMode before = lastMode;
        lastMode = mode;
        endContest(t);
        contestOpen = false;                              // a set piece, not a contest, moves the ball next
        Side owner = mode.owner();
        if (isKickOff(mode) && owner != null) teams.get(owner).kickOffs++;
        if (mode == PlayMode.PLAY_ON && isKickOff(before)) {
            kickOffTeam = before.owner();
            kickOffPlayOnAt = t;
        } else {
            boolean freeKick = mode == PlayMode.FREE_KICK_LEFT || mode == PlayMode.FREE_KICK_RIGHT;
            if (freeKick && kickOffTeam != null && owner != kickOffTeam && t - kickOffPlayOnAt <= KICK_OFF_FOUL_S)
                teams.get(kickOffTeam).kickOffFouls++;
            kickOffTeam = null;
        }
        String kind = switch (mode) {
            case FREE_KICK_LEFT, FREE_KICK_RIGHT -> "free_kick";
            case DIRECT_FREE_KICK_LEFT, DIRECT_FREE_KICK_RIGHT -> "direct_free_kick";
            case KICK_IN_LEFT, KICK_IN_RIGHT -> "kick_in";
            case CORNER_KICK_LEFT, CORNER_KICK_RIGHT -> "corner";
            case GOAL_KICK_LEFT, GOAL_KICK_RIGHT -> "goal_kick";
            case OFFSIDE_LEFT, OFFSIDE_RIGHT -> "offside";
            default -> null;
        };
        if (kind != null && owner != null) teams.get(owner).setPieces.merge(kind, 1, Integer::sum);
    }

    /** A new goal of this side: its shot is its last kick if that ended at the other side's goal line. */
    private void scored(Side side, int score, double t) {
        TeamStats ts = teams.get(side);
        if (score <= ts.goals) return;
        ts.goals = score;
        endKick(lastBall);                                // the ball went in while still rolling
        KickEvent shot = null;
        for (int i = kickEvents.size() - 1; i >= 0 && shot == null; i--) {
            KickEvent k = kickEvents.get(i);
            if (t - k.time() > GOAL_SHOT_S) break;
            if (k.team() == side && Math.abs(k.x1()) >= FIELD_HALF_LENGTH - SHOT_END_M) shot = k;
        }
        goalEvents.add(new Goal(t, side, shot, defence(side == Side.LEFT ? Side.RIGHT : Side.LEFT, lastBall)));
    }

    private Defence defence(Side side, double[] ball) {
        double[][] torsos = lastTorso[side.ordinal()];
        double nearest = Double.POSITIVE_INFINITY;
        for (int u = 1; u <= players && ball != null; u++) {
            if (torsos[u] != null) nearest = Math.min(nearest, Math.hypot(torsos[u][0] - ball[0], torsos[u][1] - ball[1]));
        }
        return new Defence(torsos[1] == null ? null : torsos[1].clone(), nearest);
    }

    private static boolean isKickOff(PlayMode m) { return m == PlayMode.KICK_OFF_LEFT || m == PlayMode.KICK_OFF_RIGHT; }

    private void step(PlayMode mode, double dt, double[] ball) {
        boolean playOn = mode == PlayMode.PLAY_ON;
        boolean beamsAllowed = mode.allowsBeam();
        double bestD = Double.POSITIVE_INFINITY;
        Side nearest = null;
        boolean[] atBall = new boolean[2];
        for (Side side : Side.values()) {
            TeamStats ts = teams.get(side);
            for (int u = 1; u <= players; u++) {
                MonitorScene.Pose p = scene.torso(u, side == Side.LEFT ? "Left" : "Right");
                double[] last = lastTorso[side.ordinal()][u];
                if (p == null) { lastTorso[side.ordinal()][u] = null; continue; }
                boolean lying = p.upZ() < LYING_UP_Z;
                boolean held = p.z() >= HELD_Z;
                if (last != null && held && lastZ[side.ordinal()][u] < HELD_Z && !beamsAllowed) foul(side, u, last, ball, state.time());
                lastZ[side.ordinal()][u] = p.z();
                if (held) continue;                       // in the air: neither a fall nor a torso near the ball
                if (last != null) {
                    if (lying && !(last[2] < LYING_UP_Z)) ts.falls++;
                    if (!beamsAllowed && dt <= 0.1 && Math.hypot(p.x() - last[0], p.y() - last[1]) > RELOCATION_M) ts.relocated++;
                }
                if (lying) ts.lyingS += dt;
                lastTorso[side.ordinal()][u] = new double[] {p.x(), p.y(), p.upZ()};
                double d = Math.hypot(p.x() - ball[0], p.y() - ball[1]);
                if (d < bestD) { bestD = d; nearest = side; }
                if (!lying && d <= CONTEST_RANGE) atBall[side.ordinal()] = true;
            }
        }
        if (playOn) {
            playOnS += dt;
            if (nearest != null) teams.get(nearest).possessionS += dt;
            double x = ball[0];
            TeamStats left = teams.get(Side.LEFT), right = teams.get(Side.RIGHT);
            if (x < -THIRD_X) { left.ownThirdS += dt; right.opponentThirdS += dt; }
            else if (x > THIRD_X) { left.opponentThirdS += dt; right.ownThirdS += dt; }
            else { left.middleS += dt; right.middleS += dt; }
            int cx = (int) Math.floor(x + 15), cy = (int) Math.floor(ball[1] + 10);
            if (cx >= 0 && cx < 30 && cy >= 0 && cy < 20) ballCells[cx][cy] += dt;
        }
        if (lastBall == null) return;
        double speed = Math.hypot(ball[0] - lastBall[0], ball[1] - lastBall[1]) / dt;
        double now = state.time();
        if (playOn && speed < CONTEST_STILL_SPEED && atBall[0] && atBall[1]) {
            if (Double.isNaN(contestStart)) contestStart = now;
        } else {
            endContest(now);
        }
        if (speed > TELEPORT_SPEED) {
            kick = null;                                  // placed, not kicked
            contestOpen = false;
        } else if (kick == null && lastBallSpeed < REST_SPEED && speed > KICK_SPEED) {
            Side kicker = kicker(lastBall);
            if (kicker != null && contestOpen) teams.get(kicker).contestsWon++;
            if (kicker != null) contestOpen = false;
            if (kicker != null) kick = new Kick(kicker, lastTime, lastBall[0], lastBall[1], ball[0] - lastBall[0], ball[1] - lastBall[1],
                    defence(kicker == Side.LEFT ? Side.RIGHT : Side.LEFT, lastBall));
        } else if (kick != null && speed < STOP_SPEED) {
            endKick(ball);
        }
        lastBallSpeed = speed > TELEPORT_SPEED ? 0 : speed;
    }

    /** Reads the server's {@code (foul index type team unum)} records of this message (team 1 left, 2 right). */
    private void namedFouls(String message, double t) {
        for (int at = message.indexOf("(foul "); at >= 0; at = message.indexOf("(foul ", at + 6)) {
            int end = message.indexOf(')', at);
            if (end < 0) return;
            String[] f = message.substring(at + 6, end).trim().split("\\s+");
            if (f.length != 4) continue;
            try {
                Foul.Kind kind = Foul.Kind.ofServer(Integer.parseInt(f[1]));
                int team = Integer.parseInt(f[2]), unum = Integer.parseInt(f[3]);
                if (kind == null || team < 1 || team > 2 || unum < 1 || unum > 11) continue;
                Side side = team == 1 ? Side.LEFT : Side.RIGHT;
                if (kind == Foul.Kind.SELF_COLLISION) teams.get(side).selfCollisions++;
                namedKind[side.ordinal()][unum] = kind;
                namedAt[side.ordinal()][unum] = t;
            } catch (NumberFormatException e) {
                // not a foul record of this format: leave it
            }
        }
    }

    /** A foul of player {@code u}, held up now; {@code last} is where and how he was in the picture before. */
    private void foul(Side side, int u, double[] last, double[] ball, double now) {
        TeamStats ts = teams.get(side);
        Foul.Kind named = namedKind[side.ordinal()][u];
        Foul.Kind kind;
        if (named != null && named != Foul.Kind.SELF_COLLISION && now - namedAt[side.ordinal()][u] <= NAMED_WITHIN_S) kind = named;
        else if (last[2] < LYING_UP_Z) kind = Foul.Kind.INCAPABLE;
        else if (u != 1 && insideOwnArea(side, last) && fieldPlayersInOwnArea(side) > MAX_IN_OWN_AREA) kind = Foul.Kind.ILLEGAL_DEFENCE;
        else kind = Foul.Kind.CONTACT;
        ts.fouls.merge(kind, 1, Integer::sum);
        double ownBall = Math.hypot(last[0] - ball[0], last[1] - ball[1]);
        double nearest = Double.POSITIVE_INFINITY, nearestBall = Double.NaN;
        for (double[] o : lastTorso[side == Side.LEFT ? 1 : 0]) {
            if (o == null) continue;
            double d = Math.hypot(o[0] - last[0], o[1] - last[1]);
            if (d < nearest) { nearest = d; nearestBall = Math.hypot(o[0] - ball[0], o[1] - ball[1]); }
        }
        foulEvents.add(new Foul(lastTime, side, u, last[0], last[1], kind, ownBall, nearest, nearestBall < ownBall));
    }

    private static boolean insideOwnArea(Side side, double[] p) {
        double fromLine = side == Side.LEFT ? p[0] + FIELD_HALF_LENGTH : FIELD_HALF_LENGTH - p[0];
        return fromLine <= PENALTY_LENGTH && Math.abs(p[1]) <= PENALTY_HALF_WIDTH;
    }

    private int fieldPlayersInOwnArea(Side side) {
        int n = 0;
        for (int u = 2; u <= players; u++) {
            double[] p = lastTorso[side.ordinal()][u];
            if (p != null && insideOwnArea(side, p)) n++;
        }
        return n;
    }

    /** The team of the torso nearest the ball, if one is within reach. */
    private Side kicker(double[] ball) {
        double best = KICKER_RANGE;
        Side team = null;
        for (Side side : Side.values()) {
            for (int u = 1; u <= players; u++) {
                double[] t = lastTorso[side.ordinal()][u];
                if (t == null) continue;
                double d = Math.hypot(t[0] - ball[0], t[1] - ball[1]);
                if (d < best) { best = d; team = side; }
            }
        }
        return team;
    }

    /** The contest going on, if any, ends now: counted when it lasted CONTEST_MIN_S, and open until the next kick. */
    private void endContest(double t) {
        if (Double.isNaN(contestStart)) return;
        if (t - contestStart >= CONTEST_MIN_S) {
            contests++;
            contestS += t - contestStart;
            contestOpen = true;
        }
        contestStart = Double.NaN;
    }

    private void endKick(double[] end) {
        Kick k = kick;
        kick = null;
        if (k == null || end == null) return;
        TeamStats ts = teams.get(k.team());
        double dist = Math.hypot(end[0] - k.x0(), end[1] - k.y0());
        ts.kicks++;
        if (dist > 8) ts.kicksOver8m++;
        if (dist < 1.5) ts.kicksUnder1_5m++;
        double goalX = k.team() == Side.LEFT ? FIELD_HALF_LENGTH : -FIELD_HALF_LENGTH;
        boolean onGoal = false;
        if (Math.signum(k.dx()) == Math.signum(goalX)) {
            double yAtLine = k.y0() + k.dy() * (goalX - k.x0()) / k.dx();
            onGoal = Math.abs(yAtLine) <= GOAL_HALF_WIDTH && Math.abs(goalX - end[0]) <= SHOT_END_M;
        }
        if (onGoal) ts.shotsOnGoal++;
        kickEvents.add(new KickEvent(k.t0(), k.team(), k.x0(), k.y0(), end[0], end[1], dist, onGoal, k.defence()));
    }

    /** The machine-readable line of one team. */
    public String line(Side side) {
        TeamStats t = teams.get(side);
        double p = playOnS > 0 ? playOnS : Double.NaN;
        return String.format(Locale.ROOT, "game-stats side=%s team=%s goals=%d shots_on_goal=%d kicks=%d kicks_over_8m=%d"
                        + " kicks_under_1_5m=%d possession=%.3f ball_own_third=%.3f ball_middle=%.3f ball_opponent_third=%.3f"
                        + " falls=%d lying_s=%.1f relocated=%d free_kicks=%d direct_free_kicks=%d kick_ins=%d corners=%d"
                        + " goal_kicks=%d offsides=%d kick_offs=%d kick_off_fouls=%d play_on_s=%.1f contests=%d contests_won=%d contest_s=%.1f"
                        + " fouls_charging=%d fouls_touching=%d fouls_contact=%d fouls_incapable=%d fouls_illegal_defence=%d"
                        + " fouls_other=%d self_collisions=%d",
                side == Side.LEFT ? "left" : "right", t.name == null ? "?" : t.name, t.goals, t.shotsOnGoal, t.kicks,
                t.kicksOver8m, t.kicksUnder1_5m, t.possessionS / p, t.ownThirdS / p, t.middleS / p, t.opponentThirdS / p,
                t.falls, t.lyingS, t.relocated, t.setPiece("free_kick"), t.setPiece("direct_free_kick"), t.setPiece("kick_in"),
                t.setPiece("corner"), t.setPiece("goal_kick"), t.setPiece("offside"), t.kickOffs, t.kickOffFouls, playOnS,
                contests, t.contestsWon, contestS,
                t.fouls(Foul.Kind.CHARGING), t.fouls(Foul.Kind.TOUCHING), t.fouls(Foul.Kind.CONTACT), t.fouls(Foul.Kind.INCAPABLE),
                t.fouls(Foul.Kind.ILLEGAL_DEFENCE), t.fouls(Foul.Kind.CROWDING) + t.fouls(Foul.Kind.ILLEGAL_ATTACK) + t.fouls(Foul.Kind.KICK_OFF),
                t.selfCollisions);
    }

    /** A ball heat map over the PlayOn time: the field in 1 m cells, darker where the ball spent longer. */
    public String svg() {
        double max = 0;
        for (double[] col : ballCells) for (double v : col) max = Math.max(max, v);
        StringBuilder b = new StringBuilder("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-16 -12 32 24\" width=\"640\" height=\"480\">\n");
        b.append("<rect x=\"-16\" y=\"-12\" width=\"32\" height=\"24\" fill=\"#2e7d32\"/>\n");
        for (int x = 0; x < 30; x++) {
            for (int y = 0; y < 20; y++) {
                if (ballCells[x][y] <= 0) continue;
                b.append(String.format(Locale.ROOT, "<rect x=\"%d\" y=\"%d\" width=\"1\" height=\"1\" fill=\"#ff6f00\" fill-opacity=\"%.3f\"/>\n",
                        x - 15, 9 - y, 0.15 + 0.85 * ballCells[x][y] / max));
            }
        }
        b.append("<rect x=\"-15\" y=\"-10\" width=\"30\" height=\"20\" fill=\"none\" stroke=\"white\" stroke-width=\"0.08\"/>\n");
        b.append("<line x1=\"0\" y1=\"-10\" x2=\"0\" y2=\"10\" stroke=\"white\" stroke-width=\"0.08\"/>\n");
        b.append("<rect x=\"-15.6\" y=\"-1.05\" width=\"0.6\" height=\"2.1\" fill=\"none\" stroke=\"white\" stroke-width=\"0.08\"/>\n");
        b.append("<rect x=\"15\" y=\"-1.05\" width=\"0.6\" height=\"2.1\" fill=\"none\" stroke=\"white\" stroke-width=\"0.08\"/>\n");
        b.append(String.format(Locale.ROOT, "<text x=\"0\" y=\"-10.6\" font-size=\"1\" fill=\"black\" text-anchor=\"middle\">%s %d:%d %s (ball, %.0f s of PlayOn)</text>\n",
                esc(teams.get(Side.LEFT).name), state.scoreLeft(), state.scoreRight(), esc(teams.get(Side.RIGHT).name), playOnS));
        return b.append("</svg>\n").toString();
    }

    /** One goal as a line: who scored when, the shot and where the defending keeper and nearest defender were. */
    static String describe(Goal g) {
        String side = g.scorer() == Side.LEFT ? "left" : "right";
        KickEvent k = g.shot();
        String shot = k == null ? "walked in" : String.format(Locale.ROOT, "shot t=%.2f from (%.2f,%.2f) %.2f m to the line, %s",
                k.time(), k.x0(), k.y0(), FIELD_HALF_LENGTH - Math.abs(k.x0()), defence("at the shot", k.defence()));
        return String.format(Locale.ROOT, "goal t=%.2f %s: %s; %s", g.time(), side, shot, defence("at the goal", g.atGoal()));
    }

    /** One foul as a line. */
    static String describe(Foul f) {
        return String.format(Locale.ROOT, "foul t=%.2f %s %d %s at (%.2f,%.2f): ball %.2f m, nearest opponent %.2f m%s",
                f.time(), f.side() == Side.LEFT ? "left" : "right", f.unum(), f.kind().key().replace('_', ' '),
                f.x(), f.y(), f.ballDistance(), f.nearestOpponent(), f.opponentNearerBall() ? " (nearer the ball)" : "");
    }

    private static String defence(String when, Defence d) {
        String keeper = d.keeper() == null ? "no keeper" : String.format(Locale.ROOT, "keeper (%.2f,%.2f)%s",
                d.keeper()[0], d.keeper()[1], d.keeperLying() ? " lying" : "");
        return String.format(Locale.ROOT, "%s %s, nearest defender %.2f m", when, keeper, d.nearest());
    }

    private static String esc(String s) {
        return s == null ? "?" : s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** Reads a monitor log, plain or gzipped, one message a line. */
    /** The robot's torso in the scene as it stands now, {x, y, upZ} (upZ below 0.5: lying), or null when not on the field. */
    public double[] torso(Side side, int unum) {
        if (unum < 1 || unum > players || !scene.hasScene()) return null;
        MonitorScene.Pose p = scene.torso(unum, side == Side.LEFT ? "Left" : "Right");
        return p == null ? null : new double[] {p.x(), p.y(), p.upZ(), p.forwardZ(), p.rightZ()};
    }

    /** The ball in the scene as it stands now, {x, y, z}, or null before the first scene. */
    public double[] ball() {
        double[] b = scene.hasScene() ? scene.ball() : null;
        return b == null ? null : b.clone();
    }

    public static GameStats read(Path log, int players) throws IOException {
        return read(log, players, g -> { });
    }

    /** As {@link #read(Path, int)}, calling {@code afterEach} after every message (for a robot's track). */
    public static GameStats read(Path log, int players, java.util.function.Consumer<GameStats> afterEach) throws IOException {
        GameStats g = new GameStats(players);
        try (InputStream raw = Files.newInputStream(log);
             InputStream in = log.toString().endsWith(".gz") ? new GZIPInputStream(raw) : raw;
             BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.ISO_8859_1))) {
            for (String line; (line = r.readLine()) != null; ) {
                if (line.isBlank()) continue;
                g.accept(line);
                afterEach.accept(g);
            }
        }
        return g;
    }

    static final String USAGE = """
            usage: scripts/phalanx stats game MONITOR_LOG [--svg OUT.svg] [--kicks] [--goals] [--fouls] [--players 11]
              MONITOR_LOG is a match's monitor.log.gz (scripts/phalanx match records one per match) or any
              monitor stream saved one message a line; prints one game-stats line per team;
              --kicks also lists every kick (time, team, from, to, length);
              --goals every goal: its shot (from where, how long, the defence when it left) or walked in;
              --fouls every player the referee took off: who, what for (the server's word when its monitor
              stream names fouls, else contact, incapable or illegal defence), where, the ball and the nearest opponent;
              --track left:1 a robot's torso (x, y, lying or up, its tilt forward and to the right) and the ball every --every S game seconds
              (default 1), between --from and --to (game time); repeat --track for more robots""";

    /** A robot named on the command line, {@code left:1}. */
    record Tracked(Side side, int unum) {
        static Tracked parse(String s) {
            String[] a = s.split(":");
            if (a.length == 2 && (a[0].equals("left") || a[0].equals("right"))) {
                try {
                    int u = Integer.parseInt(a[1]);
                    if (u >= 1 && u <= 11) return new Tracked(a[0].equals("left") ? Side.LEFT : Side.RIGHT, u);
                } catch (NumberFormatException e) { /* refused below */ }
            }
            throw new IllegalArgumentException("game-stats: --track wants left:N or right:N with N 1-11, got '" + s + "'");
        }

        String line(double t, GameStats g) {
            double[] p = g.torso(side, unum), b = g.ball();
            String who = (side == Side.LEFT ? "left " : "right ") + unum;
            // tilt: how far the torso's forward (right) axis points below the horizon, degrees
            String robot = p == null ? "not on the field" : String.format(Locale.ROOT, "(%.2f,%.2f) %s tilt %+d fwd %+d right",
                    p[0], p[1], p[2] < LYING_UP_Z ? "lying" : "up", Math.round(-Math.toDegrees(Math.asin(p[3]))), Math.round(-Math.toDegrees(Math.asin(p[4]))));
            String ball = b == null ? "" : String.format(Locale.ROOT, " ball (%.2f,%.2f)", b[0], b[1]);
            return String.format(Locale.ROOT, "track t=%.2f %s %s%s", t, who, robot, ball);
        }
    }

    public static void main(String[] argv) {
        Path log = null, svg = null;
        int players = 11;
        boolean listKicks = false, listGoals = false, listFouls = false;
        java.util.List<Tracked> tracked = new java.util.ArrayList<>();
        double every = 1, from = 0, to = Double.POSITIVE_INFINITY;
        try {
            for (String[] p : Flags.pairs(argv.length > 0 && !argv[0].startsWith("-") ? java.util.Arrays.copyOfRange(argv, 1, argv.length) : argv, USAGE, java.util.Set.of("--kicks", "--goals", "--fouls"))) {
                switch (p[0]) {
                    case "--kicks" -> listKicks = true;
                    case "--goals" -> listGoals = true;
                    case "--fouls" -> listFouls = true;
                    case "--svg" -> svg = Path.of(p[1]);
                    case "--players" -> players = (int) Flags.number(p[0], p[1], 1, 11, true);
                    case "--track" -> tracked.add(Tracked.parse(p[1]));
                    case "--every" -> every = Flags.number(p[0], p[1], 0.02, 3600, false);
                    case "--from" -> from = Flags.number(p[0], p[1], 0, 1e6, false);
                    case "--to" -> to = Flags.number(p[0], p[1], 0, 1e6, false);
                    default -> throw Flags.unknown(p[0], USAGE);
                }
            }
            if (argv.length == 0 || argv[0].startsWith("-")) throw new IllegalArgumentException("game-stats: a monitor log is needed\n" + USAGE);
            log = Path.of(argv[0]);
            if (!Files.isRegularFile(log)) throw new IllegalArgumentException("game-stats: no file " + log);
        } catch (IllegalArgumentException e) {
            boolean help = e.getMessage().equals(USAGE);
            (help ? System.out : System.err).println(e.getMessage());
            System.exit(help ? 0 : 2);
        }
        try {
            double step = every, start = from, end = to;
            double[] next = {start};
            GameStats g = read(log, players, tracked.isEmpty() ? x -> { } : x -> {
                double t = x.state().time();
                if (!Double.isFinite(t) || t < next[0] || t > end) return;
                for (Tracked r : tracked) System.out.println(r.line(t, x));
                next[0] = t + step - 1e-6;
            });
            if (g.messages() == 0 || !g.scene.hasScene()) {
                System.err.println("game-stats: " + log + " holds no monitor scene (" + g.messages() + " lines read)");
                System.exit(1);
            }
            System.out.println(g.line(Side.LEFT));
            System.out.println(g.line(Side.RIGHT));
            if (listKicks) {
                for (KickEvent k : g.kicks()) {
                    System.out.println(String.format(Locale.ROOT, "kick t=%.2f %s (%.2f,%.2f) -> (%.2f,%.2f) %.2f m%s", k.time(),
                            k.team() == Side.LEFT ? "left" : "right", k.x0(), k.y0(), k.x1(), k.y1(), k.length(), k.onGoal() ? " on goal" : ""));
                }
            }
            if (listGoals) for (Goal goal : g.goals()) System.out.println(describe(goal));
            if (listFouls) for (Foul f : g.fouls()) System.out.println(describe(f));
            if (g.unreadable() > 0) System.err.println("game-stats: " + g.unreadable() + " of " + g.messages() + " lines were not monitor messages and were skipped");
            if (svg != null) {
                Files.writeString(svg, g.svg());
                System.err.println("game-stats: wrote " + svg);
            }
        } catch (IOException e) {
            System.err.println("game-stats: cannot read " + log + ": " + e.getMessage());
            System.exit(1);
        }
    }
}

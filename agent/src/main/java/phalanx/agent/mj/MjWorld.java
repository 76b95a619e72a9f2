package phalanx.agent.mj;

import phalanx.comm.mj.MjPerception;
import phalanx.model.field.Angles;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.model.robot.T1Model;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * What a T1 player on rcssservermj knows, in its team's own frame (the world frame for the left team, turned by
 * 180° for the right): its pose from the server's ground-truth torso sensors, the ball from its own vision through
 * the camera chain ({@link T1Model#seenToWorld}), the play mode and our side. No filter: the server's pose and
 * noiseless vision need none (docs/rcssservermj.md); the thesis filter runs on SimSpark only, so far. Also the other
 * players it sees (their low parts, for who is at the ball); a set piece's first perception moves the ball where the referee drops it (soccer_referee.py), so a player that does not see it then still
 * keeps the right distance from it.
 */
public final class MjWorld {
    /** Below this z of the torso's up axis (about 60° of tilt) the robot counts as fallen. */
    static final double UPRIGHT_MIN = 0.5;

    /** Seen players' parts below this height (m) count as their feet and legs: what can touch a ball on the ground. */
    static final double LOW_PART_Z = 0.3;
    /** Nothing on the field is farther than this from a player on it (the 55 x 36 m field's diagonal is 66 m), m. */
    static final double MAX_SEEN_M = 100;
    /** A seen player is forgotten this long after it was last seen, s. */
    static final double PLAYER_FRESH_S = 2.0;

    /** A player seen by its parts (own frame, on the ground), with when; mate: of our team. */
    record SeenPlayer(boolean mate, String id, List<Vector2> parts, List<Vector2> low, double time) {}

    private final String team;
    private final MjField field;
    private final Map<String, SeenPlayer> players = new HashMap<>();
    private int side;           // +1 left, -1 right, 0 unknown yet
    private double time = Double.NaN;
    private double gameTime = Double.NaN;
    private String playMode = "";
    private Pose2 self;
    private boolean upright = true;
    private Vector2 ball;
    private double ballSeenAt = Double.NEGATIVE_INFINITY;
    private long updates;

    public MjWorld(String team) { this(team, MjField.SSIM); }

    public MjWorld(String team, MjField field) {
        this.team = team;
        this.field = field;
    }

    public void update(MjPerception p) {
        updates++;
        if (Double.isFinite(p.time())) time = p.time();
        if (Double.isFinite(p.gameTime())) gameTime = p.gameTime();
        if (side == 0) side = team.equals(p.teamLeft()) ? 1 : team.equals(p.teamRight()) ? -1 : 0;
        if (p.playMode() != null && !p.playMode().equals(playMode)) {
            playMode = p.playMode();
            dropBall();
        }
        if (p.quat() != null && p.pos() != null) {
            double heading = T1Model.headingDeg(p.quat());
            self = own(new Pose2(p.pos()[0], p.pos()[1], heading));
            upright = T1Model.uprightness(p.quat()) >= UPRIGHT_MIN;
            double[] yaw = p.joints().get("q_hj1"), pitch = p.joints().get("q_hj2");
            Map<String, SeenPlayer> now = new HashMap<>();
            for (MjPerception.Seen s : p.seen()) {
                if (yaw == null || pitch == null) break;
                double[] w = T1Model.seenToWorld(p.quat(), p.pos(), yaw[0], pitch[0], s.distance(), s.azimuth(), s.elevation());
                // a bad polar (not a number, or farther than anything on the field): no sighting
                if (!(s.distance() <= MAX_SEEN_M) || !(Double.isFinite(w[0]) && Double.isFinite(w[1]) && Double.isFinite(w[2]))) continue;
                Vector2 at = own(new Vector2(w[0], w[1]));
                if (s.name().equals("B")) {
                    ball = at;
                    ballSeenAt = time;
                } else if (s.name().startsWith("P ")) {
                    seenPart(now, s.name(), at, w[2]);
                }
            }
            players.values().removeIf(q -> !(time - q.time() <= PLAYER_FRESH_S));
            players.putAll(now);
        }
    }

    /** One part of a seen player, named "P team id part" by the parser. */
    private void seenPart(Map<String, SeenPlayer> now, String name, Vector2 at, double z) {
        String[] f = name.split(" ");
        if (f.length < 4) return;
        String key = f[1] + " " + f[2];
        SeenPlayer q = now.computeIfAbsent(key, k -> new SeenPlayer(f[1].equals(team), f[2], new ArrayList<>(), new ArrayList<>(), time));
        q.parts().add(at);
        if (z < LOW_PART_Z) q.low().add(at);
    }

    /**
     * Where the referee puts the ball as a set piece starts (soccer_referee.py): kick-off on the centre spot, goal kick
     * in the goalie area's centre, corner at the corner on the ball's side, kick-in on the touch line at the ball's x;
     * a free kick leaves it where it lies. Our own sighting replaces it as soon as we see the ball.
     */
    private void dropBall() {
        double hx = field.halfLength(), hy = field.halfWidth();
        Vector2 world = ball == null ? null : own(ball);   // own() is its own inverse
        Vector2 drop = switch (playMode) {
            case "KickOff_Left", "KickOff_Right" -> Vector2.ZERO;
            case "goal_kick_left" -> new Vector2(-hx + field.goalieArea()[0] / 2, 0);
            case "goal_kick_right" -> new Vector2(hx - field.goalieArea()[0] / 2, 0);
            case "corner_kick_left" -> world == null ? null : new Vector2(hx, Math.copySign(hy, world.y()));
            case "corner_kick_right" -> world == null ? null : new Vector2(-hx, Math.copySign(hy, world.y()));
            case "KickIn_Left", "KickIn_Right" -> world == null ? null : new Vector2(world.x(), Math.copySign(hy, world.y()));
            default -> null;
        };
        if (drop == null) return;
        ball = own(drop);
        ballSeenAt = time;
    }

    private Pose2 own(Pose2 world) {
        return side >= 0 ? world : new Pose2(-world.x(), -world.y(), Angles.normalize(world.thetaDeg() + 180));
    }

    private Vector2 own(Vector2 world) {
        return side >= 0 ? world : new Vector2(-world.x(), -world.y());
    }

    /** +1 when we play on the left, -1 on the right, 0 before the server has named us. */
    public int side() { return side; }
    public double time() { return time; }
    /** The game's play time (GS t: 0-300 in the first half, 300-600 in the second), NaN before the first. */
    public double gameTime() { return gameTime; }
    public String playMode() { return playMode; }
    /** Our pose in our own frame, null before the first torso reading. */
    public Pose2 self() { return self; }
    public boolean upright() { return upright; }
    /** The ball in our own frame as last seen, null if never seen. */
    public Vector2 ball() { return ball; }
    /** Seconds since the ball was last seen (infinite if never). */
    public double ballAge() { return ball == null ? Double.POSITIVE_INFINITY : time - ballSeenAt; }
    public long updates() { return updates; }
    /** The players seen in the last {@link #PLAYER_FRESH_S} s, each as last seen. */
    public List<SeenPlayer> players() { return List.copyOf(players.values()); }

    /** Some player seen in this very perception has a low part within {@code within} m of the ball (false without a ball). */
    public boolean otherAtBall(double within) {
        if (ball == null) return false;
        for (SeenPlayer q : players.values()) {
            if (q.time() != time) continue;
            for (Vector2 v : q.low()) if (v.distanceTo(ball) < within) return true;
        }
        return false;
    }

    /** The nearest distance from {@code p} to any part of an opponent seen in the last {@link #PLAYER_FRESH_S} s (infinite if none). */
    public double opponentDistance(Vector2 p) {
        double best = Double.POSITIVE_INFINITY;
        for (SeenPlayer q : players.values()) {
            if (q.mate()) continue;
            for (Vector2 v : q.parts()) best = Math.min(best, v.distanceTo(p));
        }
        return best;
    }

    /** Whether the server lets robots beam now (games/soccer/sim/soccer_referee.py is_beaming_allowed). */
    public boolean beamAllowed() {
        return playMode.equals("BeforeKickOff") || playMode.startsWith("Goal_");
    }

    /** True for a play mode that is ours: "KickOff_Left" when we are left, and so on. */
    public boolean ours(String mode) {
        String m = mode.toLowerCase();
        return side > 0 ? m.endsWith("_left") : side < 0 && m.endsWith("_right");
    }
}

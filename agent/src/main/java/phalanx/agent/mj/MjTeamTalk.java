package phalanx.agent.mj;

import phalanx.agent.team.Reports;
import phalanx.agent.team.RoundPlanner;
import phalanx.agent.team.TeamChannel;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.comm.team.Action;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.MjTeamMessageCodec;
import phalanx.comm.team.SayCodec;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessage;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.Coordinator;
import phalanx.coordination.formation.StretchedFormation;
import phalanx.coordination.support.DynamicProgrammingSupportMapper;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.Base64;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;

/**
 * The T1 team's channel on rcssservermj: the thesis's coordination rounds (5.3) exactly as the SimSpark players run
 * them ({@link TeamChannel}: CoordinatorRounds on the goalkeeper, FieldPlayerRounds on the others), over
 * {@link MjTeamMessageCodec}'s 10-byte frames and {@link ChannelConfig#MJ}. On the goalkeeper a {@link RoundPlanner}
 * plans each round with the coordination module on the 55 x 36 m field, with the formation stretched to it
 * ({@link StretchedFormation}, the spots {@link MjBehaviour} walks to without orders). Each player also keeps its
 * team-mates' last reported places, for the rule it follows while it has no order ({@link #nearestToBall}).
 */
final class MjTeamTalk {
    /** A team-mate's report older than this no longer counts for {@link #nearestToBall}. */
    static final double FRESH_S = 2.0;

    record Mate(Pose2 pose, double time) {}

    private final int unum;
    private final MjWorld world;
    private final TeamChannel channel;
    private final BooleanSupplier barred;
    private final Map<Integer, Mate> mates = new HashMap<>();
    private long accepted;

    MjTeamTalk(TeamKey key, String team, int unum, MjField field, MjWorld world) {
        this(key, team, unum, field, world, () -> false, () -> false);
    }

    /**
     * {@code keeperHasBall}: on the goalkeeper, its Libero state (the coordination's Support mode, 5.2);
     * {@code barred}: the double-touch rule bars this player from the ball ({@link MjTouchRule}), reported as X.
     */
    MjTeamTalk(TeamKey key, String team, int unum, MjField field, MjWorld world, BooleanSupplier keeperHasBall, BooleanSupplier barred) {
        this.unum = unum;
        this.world = world;
        this.barred = barred;
        ChannelConfig config = ChannelConfig.MJ.withPlayers(field.players());
        SayCodec codec = new MjTeamMessageCodec(key, config).text();
        if (unum != config.coordinator()) {
            channel = TeamChannel.fieldPlayer(config, codec, team, unum);
            return;
        }
        StretchedFormation formation = new StretchedFormation(field, CoordinationConfig.THESIS.formation());
        Coordinator coordinator = new Coordinator(CoordinationConfig.THESIS, new DynamicProgrammingSupportMapper(),
                (ball, plane) -> formation.generate(ball));
        RoundPlanner planner = new RoundPlanner(coordinator, field.spec(), unum, () -> PlayMode.fromWire(world.playMode()),
                keeperHasBall, () -> new RoundPlanner.Own(report(unum, world, barred.getAsBoolean()), side(world), world.ball()));
        channel = TeamChannel.coordinator(config, codec, team, planner);
    }

    /**
     * One cycle, after the world has taken the perception: hears its messages (as the base64 text the rounds decode),
     * steps the rounds, keeps the reports heard; returns the frame to say, or null.
     */
    byte[] step(MjPerception p) {
        if (!Double.isFinite(p.time())) return null;   // no clock: no cycle, no slot
        List<Hear> heard = new ArrayList<>(p.heard().size());
        for (MjPerception.Heard h : p.heard()) {
            // rcssservermj labels no message with a team and never echoes one's own: the keyed check tells ours
            heard.add(new Hear(null, p.time(), false, h.azimuth(), Base64.getEncoder().encodeToString(h.bytes())));
        }
        PlayMode mode = p.playMode() == null ? null : PlayMode.fromWire(p.playMode());
        String say = channel.step(MjTeamMessageCodec.cycleOf(p.time()), mode, heard, () -> report(unum, world, barred.getAsBoolean()));
        for (TeamMessage.Report r : channel.heardReports()) {
            accepted++;
            if (r instanceof TeamMessage.Complete c) mates.put(c.sender(), new Mate(new Pose2(c.x(), c.y(), c.thetaDeg()), world.time()));
            else if (r instanceof TeamMessage.Location l) mates.put(l.sender(), new Mate(new Pose2(l.x(), l.y(), l.thetaDeg()), world.time()));
            else mates.remove(r.sender());   // B, X: no place (a fallen mate is not going to the ball)
        }
        return say == null ? null : Base64.getDecoder().decode(say);
    }

    /**
     * What a T1 reports (5.3): its pose always (the server gives it), with the ball when seen within
     * {@link Reports#BALL_FRESH_S} (Complete, else Location); X once down, as on SimSpark.
     */
    static TeamMessage.Report report(int unum, MjWorld w) { return report(unum, w, false); }

    /**
     * As above; while {@code barred} by the double-touch rule: X (thesis 5.3: nothing the plan can use), so that the
     * coordinator counts the player inactive and gives On Ball to another, whose touch frees it. The coordination module
     * stays as it is; the player's place is missing from the plan for that while.
     */
    static TeamMessage.Report report(int unum, MjWorld w, boolean barred) {
        Pose2 s = w.self();
        if (barred && s != null && w.upright()) return new TeamMessage.Unaware(unum, false);
        if (s == null || !w.upright()) return new TeamMessage.Unaware(unum, s != null);
        Vector2 b = w.ball();
        if (b != null && w.ballAge() <= Reports.BALL_FRESH_S) return new TeamMessage.Complete(unum, s.x(), s.y(), s.thetaDeg(), b.x(), b.y());
        return new TeamMessage.Location(unum, s.x(), s.y(), s.thetaDeg());
    }

    private static Side side(MjWorld w) {
        return w.side() > 0 ? Side.LEFT : w.side() < 0 ? Side.RIGHT : null;
    }

    /** The coordinator's last order to this field player; null before the first, after it went quiet, on the goalkeeper. */
    Action order() { return channel.order(); }

    /**
     * The rule without an order (today's stop-gap, kept as FieldPlayerRounds' fallback): true when no field player
     * with a fresh report is nearer the ball than we are (ties to the lower number); the goalkeeper (1) never counts.
     */
    boolean nearestToBall(Pose2 self, Vector2 ball, double now) {
        double mine = self.position().distanceTo(ball);
        for (Map.Entry<Integer, Mate> e : mates.entrySet()) {
            int n = e.getKey();
            Mate m = e.getValue();
            if (n == 1 || now - m.time() > FRESH_S) continue;
            double theirs = m.pose().position().distanceTo(ball);
            if (theirs < mine || theirs == mine && n < unum) return false;
        }
        return true;
    }

    /**
     * A team-mate's report heard in the last {@code freshS} s puts its torso within {@code within} m of {@code ball}:
     * where it stands to kick (the double-touch rule's sign that another player has played it).
     */
    boolean mateAtBall(Vector2 ball, double within, double freshS, double now) {
        if (ball == null) return false;
        for (Mate m : mates.values()) {
            if (now - m.time() <= freshS && m.pose().position().distanceTo(ball) < within) return true;
        }
        return false;
    }

    /** Team-mates' reports heard and accepted so far. */
    long accepted() { return accepted; }
    Map<Integer, Mate> mates() { return mates; }
    TeamChannel channel() { return channel; }
}

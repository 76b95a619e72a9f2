package phalanx.agent.mj;

import phalanx.comm.mj.MjPerception;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.MjTeamMessageCodec;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessage;
import phalanx.comm.team.TeamMessageCodec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.HashMap;
import java.util.Map;

/**
 * The T1 team's talk on rcssservermj, a first step before the thesis's coordination rounds run there: each
 * player says its pose and ball (a Complete report, {@link MjTeamMessageCodec}'s 10-byte frame) in a slot of its
 * own, one speaker a cycle (the three loudest are always heard, docs/rcssservermj.md), and keeps the team-mates'
 * latest reports, so that the one nearest the ball can go to it ({@link #nearestToBall}).
 */
final class MjTeamTalk {
    /** A team-mate's report older than this no longer counts. */
    static final double FRESH_S = 2.0;

    record Mate(Pose2 pose, Vector2 ball, double time) {}

    private final int unum, players;
    private final MjTeamMessageCodec codec;
    private final Map<Integer, Mate> mates = new HashMap<>();
    private long accepted, rejected;

    MjTeamTalk(TeamKey key, int unum, int players) {
        this.unum = unum;
        this.players = players;
        this.codec = new MjTeamMessageCodec(key, ChannelConfig.DEFAULT.withPlayers(players));
    }

    /** Takes this perception's heard messages (ours pass the keyed check; an opponent's never do). */
    void hear(MjPerception p, double now) {
        long cycle = MjTeamMessageCodec.cycleOf(p.time());
        for (MjPerception.Heard h : p.heard()) {
            TeamMessageCodec.Decoded d = codec.decode(h.bytes(), cycle);
            if (d.accepted() && d.message() instanceof TeamMessage.Complete c && c.sender() != unum) {
                accepted++;
                mates.put(c.sender(), new Mate(new Pose2(c.x(), c.y(), c.thetaDeg()), new Vector2(c.ballX(), c.ballY()), now));
            } else if (!d.accepted()) {
                rejected++;
            }
        }
    }

    /** Our frame for this cycle, or null when it is not our slot or we know too little to report. */
    byte[] say(MjPerception p, Pose2 self, Vector2 ball) {
        long cycle = MjTeamMessageCodec.cycleOf(p.time());
        if (Math.floorMod(cycle, players) != unum - 1 || self == null || ball == null) return null;
        return codec.encode(new TeamMessage.Complete(unum, self.x(), self.y(), self.thetaDeg(), ball.x(), ball.y()), cycle);
    }

    /**
     * True when no field player with a fresh report is nearer the ball than we are (ties to the lower number);
     * the goalkeeper (1) never counts.
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

    long accepted() { return accepted; }
    long rejected() { return rejected; }
    Map<Integer, Mate> mates() { return mates; }
}

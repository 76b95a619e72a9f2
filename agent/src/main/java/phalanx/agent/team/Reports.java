package phalanx.agent.team;

import phalanx.comm.team.TeamMessage;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * The coordination reports of thesis 5.3 both ways: what a player says about its beliefs (C, L, B
 * or X, by what it knows), and how the coordinator reads a report into coordination's terms.
 */
public final class Reports {
    /** A self pose refreshed by vision within this many seconds counts as known (ours: 3 vision frames). */
    public static final double SELF_FRESH_S = 1.0;
    /** A ball seen within this many seconds counts as known (ours). */
    public static final double BALL_FRESH_S = 1.0;

    private Reports() {}

    /** What this player reports about itself (5.3). */
    public static TeamMessage.Report of(int unum, WorldBelief b) {
        if (b == null || b.fall().isDown()) return new TeamMessage.Unaware(unum, b != null);
        boolean self = b.knowsSelf(SELF_FRESH_S);
        // A ball heard from teammates is not reported back as seen: the coordinator would fuse it as one more sighting.
        boolean ball = !b.ballHeard() && b.ballAge() <= BALL_FRESH_S && b.ballRelative() != null;
        if (self && ball && b.ballGlobal() != null) {
            Pose2 s = b.self();
            return new TeamMessage.Complete(unum, s.x(), s.y(), s.thetaDeg(), b.ballGlobal().x(), b.ballGlobal().y());
        }
        if (self) return new TeamMessage.Location(unum, b.self().x(), b.self().y(), b.self().thetaDeg());
        if (ball) return new TeamMessage.Ball(unum, b.ballRelative().norm(), b.ballRelative().angleDeg());
        return new TeamMessage.Unaware(unum, false);
    }

    /** A report heard by the coordinator, as coordination takes it. */
    public static PlayerReport toCoordination(TeamMessage.Report r) {
        if (r instanceof TeamMessage.Complete c) {
            return PlayerReport.complete(c.sender(), new Pose2(c.x(), c.y(), c.thetaDeg()), new Vector2(c.ballX(), c.ballY()));
        }
        if (r instanceof TeamMessage.Location l) return PlayerReport.located(l.sender(), new Pose2(l.x(), l.y(), l.thetaDeg()));
        if (r instanceof TeamMessage.Ball b) return PlayerReport.ballOnly(b.sender(), b.distance(), b.angleDeg(), Double.NaN);
        TeamMessage.Unaware u = (TeamMessage.Unaware) r;
        return u.fallen() ? PlayerReport.lost(u.sender()).asFallen() : PlayerReport.lost(u.sender());
    }
}

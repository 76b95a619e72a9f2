package phalanx.agent.mj;

import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.formation.Role;
import phalanx.coordination.formation.StretchedFormation;
import phalanx.model.field.Angles;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * What a T1 player does on rcssservermj, as far as it goes today: beam to its kick-off spot while the referee
 * allows it, then the field player nearest the ball by the team's reports ({@link MjTeamTalk}) walks to the ball
 * and every other player to its spot of the thesis formation for the ball's place ({@link StretchedFormation}),
 * facing the ball. No thesis coordination rounds, kick or get-up yet (issue 20).
 */
final class MjBehaviour {
    /** A beam (own frame) or a walk command; STAND is neither. */
    record Intent(Pose2 beam, double vx, double vy, double turnDegPerS) {
        static final Intent STAND = new Intent(null, 0, 0, 0);
        static Intent beam(Pose2 p) { return new Intent(p, 0, 0, 0); }
        boolean walks() { return vx != 0 || vy != 0 || turnDegPerS != 0; }
    }

    /** Our choices for the T1 (no thesis figure exists): how fast to walk and turn, when a spot is reached. */
    record Config(double maxForward, double maxTurn, double turnFirstDeg, double arriveM, double beamToleranceM,
                  double beamRepeatS) {
        // motion/README.md "T1 gait", the balanced preset: 0.5 m/s walking and 60 °/s commanded (38 °/s turned)
        // with no fall
        static final Config DEFAULT = new Config(0.5, 60, 35, 0.4, 0.1, 1.0);
    }

    private final StretchedFormation formation;
    private final Role role;
    private final Config c;
    private double lastBeam = Double.NEGATIVE_INFINITY;

    MjBehaviour(MjField field, int unum, Config c) {
        this.formation = new StretchedFormation(field, CoordinationConfig.THESIS.formation());
        this.role = formation.role(unum);
        this.c = c;
    }

    Role role() { return role; }

    /** Our kick-off spot, own frame, facing the opponent goal. */
    Pose2 kickOffSpot() {
        Vector2 p = formation.generate(Vector2.ZERO).position(role);
        return new Pose2(p.x(), p.y(), 0);
    }

    /** As {@link #decide(MjWorld, boolean)} for a player alone: only the forward (FC) goes to the ball. */
    Intent decide(MjWorld w) {
        return decide(w, role == Role.FC);
    }

    /** {@code nearest}: no team-mate reports himself nearer the ball ({@link MjTeamTalk#nearestToBall}). */
    Intent decide(MjWorld w, boolean nearest) {
        Pose2 self = w.self();
        if (self == null || w.side() == 0) return Intent.STAND;
        if (w.beamAllowed()) {
            Pose2 spot = kickOffSpot();
            boolean there = self.position().distanceTo(spot.position()) <= c.beamToleranceM()
                    && Math.abs(Angles.difference(self.thetaDeg(), spot.thetaDeg())) < 10;
            if (there || w.time() - lastBeam < c.beamRepeatS()) return Intent.STAND;
            lastBeam = w.time();
            return Intent.beam(spot);
        }
        if (!w.upright() || w.playMode().equals("GameOver")) return Intent.STAND;
        Vector2 ball = w.ball();
        if (ball == null) return turnInPlace(self, 90);  // look around for it
        boolean kickOffTheirs = w.playMode().startsWith("KickOff") && !w.ours(w.playMode());
        if (nearest && role != Role.GK && !kickOffTheirs) return walkTo(self, ball, ball);
        return walkTo(self, formation.generate(ball).position(role), ball);
    }

    /** Turn to the target while far off its bearing, else walk at it; at the target, face {@code look}. */
    private Intent walkTo(Pose2 self, Vector2 target, Vector2 look) {
        Vector2 rel = self.toRelative(target);
        double dist = rel.norm();
        if (dist < c.arriveM()) {
            double face = self.toRelative(look).angleDeg();
            return Math.abs(face) < 15 ? Intent.STAND : turnInPlace(self, face);
        }
        double bearing = rel.angleDeg();
        double turn = Math.max(-c.maxTurn(), Math.min(c.maxTurn(), bearing));
        if (Math.abs(bearing) > c.turnFirstDeg()) return new Intent(null, 0, 0, turn);
        return new Intent(null, Math.min(c.maxForward(), dist), 0, turn);
    }

    private Intent turnInPlace(Pose2 self, double bearing) {
        return new Intent(null, 0, 0, Math.signum(bearing) * c.maxTurn());
    }
}

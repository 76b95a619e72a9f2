package phalanx.agent.mj;

import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.formation.Role;
import phalanx.coordination.formation.StretchedFormation;
import phalanx.model.field.Angles;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.motion.t1.T1KickConfig;

/**
 * What a T1 player does on rcssservermj: beam to its kick-off spot while the referee allows it, then carry out the
 * coordinator's order (thesis 5.3, {@link MjTeamTalk}): On Ball goes to the ball and kicks, Walk To Coordinate walks to
 * the point and faces the ball, any other order (Look Straight while waiting for a kick-off, Turn To Localize for a
 * player that was down) walks to its formation spot. Without an order (none yet, or the coordinator has gone quiet)
 * the field player nearest the ball by the team's reports goes to it and every other player to its spot of the
 * thesis formation for the ball's place ({@link StretchedFormation}), facing the ball. The player going to the ball
 * walks to a spot behind it on the ball-to-goal line and, once there and facing the goal, asks for a kick
 * ({@link phalanx.motion.t1.T1Kick}) with the foot on the ball's side.
 */
final class MjBehaviour {
    /** Which foot kicks. */
    enum Foot { LEFT, RIGHT }

    /** A beam (own frame), a walk command or a kick (with that foot); STAND is none. */
    record Intent(Pose2 beam, double vx, double vy, double turnDegPerS, Foot kick) {
        static final Intent STAND = new Intent(null, 0, 0, 0);
        Intent(Pose2 beam, double vx, double vy, double turnDegPerS) { this(beam, vx, vy, turnDegPerS, null); }
        static Intent beam(Pose2 p) { return new Intent(p, 0, 0, 0); }
        static Intent kick(Foot f) { return new Intent(null, 0, 0, 0, f); }
        boolean walks() { return vx != 0 || vy != 0 || turnDegPerS != 0; }
    }

    /**
     * Our choices for the T1 (no thesis figure exists): how fast to walk and turn, when a spot is reached; and the
     * kick's approach: where the ball must lie in our frame (kickBallX ahead, ±kickBallY to the kicking foot's side:
     * T1KickConfig's ballX, ballY, where the bench kicked it), how far off that we still kick (kickToleranceM) and
     * how far off the goal's direction we may face (kickAimDeg), where the kick sends the ball against our heading
     * (kickDirectionDeg, right foot; the left's is its negative: we face that much off the goal); the spot we walk to
     * lies kickBackoffM further back and the kick window's centre half that (0: tried against the gait's creep, it
     * did worse; MjRuntime's WAIT_VX handles the creep); within approachM of the spot we walk to it sideways and
     * forwards (at most fineSpeed) while turning to the goal.
     */
    record Config(double maxForward, double maxTurn, double turnFirstDeg, double arriveM, double beamToleranceM,
                  double beamRepeatS, double kickBallX, double kickBallY, double kickDirectionDeg, double kickBackoffM,
                  double kickToleranceM, double kickAimDeg, double approachM, double fineSpeed) {
        // motion/README.md "T1 gait", the balanced preset: 0.5 m/s walking and 60 °/s commanded (38 °/s turned)
        // with no fall; the kick's figures: motion/README.md "T1 kick"
        static final Config DEFAULT = new Config(0.5, 60, 35, 0.4, 0.1, 1.0,
                T1KickConfig.defaults().ballX(), T1KickConfig.defaults().ballY(), T1KickConfig.defaults().directionDeg(),
                0.0, 0.05, 20, 0.6, 0.2);  // kickBackoffM: 0.06 and 0.03 tried in MjKickTest, worse (motion/README.md "T1 kick")
    }

    private final MjField field;
    private final StretchedFormation formation;
    private final Role role;
    private final Config c;
    private double lastBeam = Double.NEGATIVE_INFINITY;

    MjBehaviour(MjField field, int unum, Config c) {
        this.field = field;
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

    /** As {@link #decide(MjWorld, Action, boolean)} for a player alone: no order, only the forward (FC) goes to the ball. */
    Intent decide(MjWorld w) {
        return decide(w, null, role == Role.FC);
    }

    /**
     * {@code order}: the coordinator's last order to this player, null when there is none (none yet, or the
     * coordinator has gone quiet); {@code nearest}: no team-mate reports himself nearer the ball
     * ({@link MjTeamTalk#nearestToBall}), the rule without an order.
     */
    Intent decide(MjWorld w, Action order, boolean nearest) {
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
        if (order != null && order.id() == ActionId.WALK_TO_COORDINATE) {
            Vector2 target = new Vector2(order.x(), order.y());
            // the coordinator's heading faces the ball it planned with; ours is fresher when we have one
            return walkTo(self, target, ball != null ? ball : target.plus(Vector2.ofAngle(order.thetaDeg())));
        }
        if (ball == null) return turnInPlace(self, 90);  // look around for it
        boolean kickOffTheirs = w.playMode().startsWith("KickOff") && !w.ours(w.playMode());
        boolean toBall = order != null ? order.id() == ActionId.ON_BALL : nearest;
        if (toBall && role != Role.GK && !kickOffTheirs) return kickToGoal(self, ball);
        return walkTo(self, formation.generate(ball).position(role), ball);
    }

    /**
     * To the spot behind the ball on the ball-to-goal line (the kicking foot's side chosen by where the ball lies
     * now), around the ball when we are in front of it; there and facing the goal: kick.
     */
    Intent kickToGoal(Pose2 self, Vector2 ball) {
        Vector2 toGoal = new Vector2(field.halfLength(), 0).minus(ball);
        Vector2 dir = toGoal.norm() < 1e-6 ? new Vector2(1, 0) : toGoal.times(1 / toGoal.norm());
        Vector2 rel = self.toRelative(ball);
        Foot foot = rel.y() >= 0 ? Foot.LEFT : Foot.RIGHT;
        double side = foot == Foot.LEFT ? 1 : -1;  // the ball lies to this side of our torso when we kick
        // the heading that sends the ball at the goal, and the torso's spot for it
        double heading = dir.angleDeg() + side * c.kickDirectionDeg();
        Vector2 ahead = Vector2.ofAngle(heading), left = new Vector2(-ahead.y(), ahead.x());
        double aim = Angles.difference(heading, self.thetaDeg());
        if (Math.abs(rel.x() - c.kickBallX() - c.kickBackoffM() / 2) < c.kickToleranceM()
                && Math.abs(rel.y() - side * c.kickBallY()) < c.kickToleranceM() && Math.abs(aim) < c.kickAimDeg()) return Intent.kick(foot);
        Vector2 spot = ball.minus(ahead.times(c.kickBallX() + c.kickBackoffM())).minus(left.times(side * c.kickBallY()));
        Vector2 fromBall = self.position().minus(ball);
        if (fromBall.dot(ahead) > -c.kickBallX() / 2 && fromBall.norm() < 1.5) {   // in front of or beside the ball: go round it
            double round = fromBall.dot(left) >= 0 ? 1 : -1;
            return walkTo(self, ball.minus(ahead.times(0.8)).plus(left.times(round * 0.6)), ball);
        }
        if (self.position().distanceTo(spot) > c.approachM()) return walkTo(self, spot, ball);
        Vector2 r = self.toRelative(spot);
        double turn = Math.max(-c.maxTurn(), Math.min(c.maxTurn(), 2 * aim));
        return new Intent(null, clamp(r.x(), c.fineSpeed()), clamp(r.y(), c.fineSpeed()), turn);
    }

    private static double clamp(double v, double limit) { return Math.max(-limit, Math.min(limit, v)); }

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

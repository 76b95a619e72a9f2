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
 * ({@link phalanx.motion.t1.T1Kick}) with the foot on the ball's side. The goalkeeper guards its line and comes out
 * for a ball it gets to first ({@link MjKeeper}).
 * <p>
 * The referee's set-piece rules are kept here, on every place any player walks to (the order's, the formation's, the
 * goalkeeper's; {@link MjSetPiece}): each player has its own fresh ball and pose, where the coordinator plans with reports
 * a round old and only for the field players. In the other side's set pieces nobody goes to the ball (the one that would
 * stands on the ball's line to our goal outside the circle); a player barred by the double-touch rule
 * ({@link MjTouchRule}) keeps {@link #KEEP_OFF_BALL_M} from the ball; and no field player's place lies in our goalie area, so
 * that only the keeper and the one going to the ball are in it (the illegal-defence rule: MjSetPiece).
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

    /**
     * Ours: a player barred by the double-touch rule keeps this far from the ball, out of the way of the team-mate the
     * coordinator sends to it (at 1 m, two runs of MjSetPieceServerTest out of eleven had a double-touch free kick 20-25 s
     * after a kick-off push, with three of ours fallen or standing within 1 m of a ball that had not moved); within
     * BACK_OFF_M it steps off without turning, from there it turns and walks (the feet sweep ~0.3 m round the torso).
     */
    static final double KEEP_OFF_BALL_M = 2.0, BACK_OFF_M = 0.6;
    /**
     * A half of the ssim rule book, s (soccer_rules.py): before the kick-off the play time tells the half, and in the
     * second the right team kicks off (MjMatch's `(kickOff Right)`, as on SimSpark); no one tells us before it is given.
     */
    static final double HALF_S = 300;

    private final MjField field;
    private final StretchedFormation formation;
    private final Role role;
    private final Config c;
    private final MjSetPiece.Config setPiece = MjSetPiece.Config.DEFAULT;
    private final MjKeeper keeper;
    private double lastBeam = Double.NEGATIVE_INFINITY;

    MjBehaviour(MjField field, int unum, Config c) {
        this.field = field;
        this.formation = new StretchedFormation(field, CoordinationConfig.THESIS.formation());
        this.role = formation.role(unum);
        this.c = c;
        this.keeper = role == Role.GK ? new MjKeeper(field, MjKeeper.Config.DEFAULT) : null;
    }

    Role role() { return role; }

    /** The goalkeeper is clearing the ball (its Libero state): the coordination's Support mode. False on field players. */
    boolean keeperHasBall() { return keeper != null && keeper.hasBall(); }

    /** The goalkeeper's state machine; null on a field player. */
    MjKeeper keeper() { return keeper; }

    /** Our kick-off spot, own frame, facing the opponent goal. */
    Pose2 kickOffSpot() { return kickOffSpot(false); }

    /**
     * The spot to beam to before a kick-off: the formation's for the ball on the centre spot (the goalkeeper: its guard
     * spot); before theirs moved out of the centre circle (the referee drops any of ours in it: MjSetPiece).
     */
    Pose2 kickOffSpot(boolean theirKickOff) {
        Vector2 p = keeper != null ? keeper.guardPoint(null) : formation.generate(Vector2.ZERO).position(role);
        // their kick-off in our own frame: the right's, seen from the left
        if (theirKickOff) p = MjSetPiece.of("KickOff_Right", 1, field, Vector2.ZERO, false, setPiece).allowed(p, field);
        return new Pose2(p.x(), p.y(), 0);
    }

    /**
     * Whether the kick-off to come is the other side's: after our goal (Goal_Left when we play left) it is; before the
     * game's, the left team kicks off in the first half and the right in the second (HALF_S).
     */
    static boolean theirKickOffNext(MjWorld w) {
        if (w.playMode().startsWith("Goal_")) return w.ours(w.playMode());
        boolean firstHalf = !(w.gameTime() >= HALF_S);
        return firstHalf ? w.side() < 0 : w.side() > 0;
    }

    /** The other side owns the play mode: its kick-off or set piece (a goal's pause and game over are nobody's). */
    static boolean theirs(MjWorld w) {
        String m = w.playMode(), lower = m.toLowerCase(java.util.Locale.ROOT);
        boolean owned = lower.endsWith("_left") || lower.endsWith("_right");
        return owned && !m.startsWith("Goal_") && !w.ours(m);
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
    Intent decide(MjWorld w, Action order, boolean nearest) { return decide(w, order, nearest, false); }

    /** As above; {@code barred}: the double-touch rule bars this player from the ball ({@link MjTouchRule}). */
    Intent decide(MjWorld w, Action order, boolean nearest, boolean barred) {
        Pose2 self = w.self();
        if (self == null || w.side() == 0) return Intent.STAND;
        if (w.beamAllowed()) {
            Pose2 spot = kickOffSpot(theirKickOffNext(w));
            boolean there = self.position().distanceTo(spot.position()) <= c.beamToleranceM()
                    && Math.abs(Angles.difference(self.thetaDeg(), spot.thetaDeg())) < 10;
            if (there || w.time() - lastBeam < c.beamRepeatS()) return Intent.STAND;
            lastBeam = w.time();
            return Intent.beam(spot);
        }
        if (!w.upright() || w.playMode().equals("GameOver")) return Intent.STAND;
        Vector2 ball = w.ball();
        boolean mayPlayBall = !theirs(w) && !barred;
        boolean toBall = role != Role.GK && (order != null ? order.id() == ActionId.ON_BALL : nearest);
        MjSetPiece rules = barred && ball != null ? MjSetPiece.around(ball, KEEP_OFF_BALL_M, 0)
                : MjSetPiece.of(w.playMode(), w.side(), field, ball, toBall && mayPlayBall, setPiece);
        if (keeper != null) return guard(w, self, ball, rules, mayPlayBall);
        if (barred && ball != null && self.position().distanceTo(ball) < BACK_OFF_M) return backOff(self, ball);
        Vector2 target, look;
        if (order != null && order.id() == ActionId.WALK_TO_COORDINATE) {
            target = new Vector2(order.x(), order.y());
            // the coordinator's heading faces the ball it planned with; ours is fresher when we have one
            look = ball != null ? ball : target.plus(Vector2.ofAngle(order.thetaDeg()));
        } else if (ball == null) {
            return turnInPlace(self, 90);  // look around for it
        } else if (toBall && mayPlayBall) {
            return kickToGoal(self, ball);
        } else {
            look = ball;
            // the one that would go to the ball in their set piece stands on its line to our goal, outside the circle
            target = toBall && rules.centre() != null && !barred ? rules.wall(ball, field) : formation.generate(ball).position(role);
        }
        target = rules.allowed(MjSetPiece.outOfOurGoalieArea(target, field, setPiece.margin()), field);
        // Near a place the referee's circle or line is close to, hold it with small steps facing the ball: standing, the
        // gait creeps forward (toward the ball we face), and walkTo would turn round to walk back (MjSetPieceServerTest:
        // the forward, beamed 6.5 m from the centre at their kick-off, was at 5.90 m after 8 s).
        if (rules.restricts() && ball != null && self.position().distanceTo(target) < c.approachM())
            return stepTo(self, target, look.minus(self.position()).angleDeg(), HOLD_TOLERANCE_M);
        return walkTo(self, rules.via(self.position(), target, setPiece), look);
    }

    /** Ours: holding a place in a set piece, a player stands once this near it (less than the gait's creep in a second). */
    static final double HOLD_TOLERANCE_M = 0.1;

    /**
     * Off the ball without turning: backwards and sideways, to the side away from the ball (left when it lies straight
     * ahead). Turning on the spot next to the ball sweeps the feet round it, and each touch now is a foul; but the gait
     * hardly walks backwards (bench t1, balanced, 2026-12-07: -0.25 m/s commanded gave -0.05 m/s, -0.1 gave +0.02, the
     * creep), while sideways it makes about 0.1 m/s (motion/README.md "T1 gait"): so mostly sideways.
     */
    private Intent backOff(Pose2 self, Vector2 ball) {
        Vector2 rel = self.toRelative(ball);
        double side = rel.y() > 0.02 ? -1 : 1;
        return new Intent(null, -c.maxForward() / 2, side * c.fineSpeed(), 0);
    }

    /** The goalkeeper: Libero (to the ball and kick) or Guard (its line; side steps near it, facing the ball). */
    private Intent guard(MjWorld w, Pose2 self, Vector2 ball, MjSetPiece rules, boolean mayPlayBall) {
        if (keeper.update(w, mayPlayBall) == MjKeeper.State.LIBERO) return kickToGoal(self, ball);
        Vector2 spot = rules.allowed(keeper.guardPoint(ball), field);
        Vector2 look = ball != null ? ball : spot.plus(new Vector2(1, 0));
        if (self.position().distanceTo(spot) > c.approachM()) return walkTo(self, rules.via(self.position(), spot, setPiece), look);
        return stepTo(self, spot, look.minus(self.position()).angleDeg(), GUARD_TOLERANCE_M);
    }

    /** Ours: the keeper stands once this near its guard point (the SimSpark keeper's shiftTolerance, AgentConfig.Keeper). */
    static final double GUARD_TOLERANCE_M = 0.15;

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
        return stepTo(self, spot, heading, c.kickToleranceM());
    }

    /**
     * The last steps to a spot near by: sideways and forwards at most fineSpeed (the T1 steps sideways at about 0.1 m/s,
     * motion/README.md "T1 gait") while turning to {@code headingDeg}; standing once within {@code tolerance} and facing it.
     */
    private Intent stepTo(Pose2 self, Vector2 spot, double headingDeg, double tolerance) {
        Vector2 r = self.toRelative(spot);
        double aim = Angles.difference(headingDeg, self.thetaDeg());
        if (r.norm() < tolerance && Math.abs(aim) < c.kickAimDeg() / 2) return Intent.STAND;
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

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.coordination.formation.Role;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

class MjBehaviourTest {
    private static final double S = Math.sqrt(0.5);
    private static final Map<String, double[]> HEAD = Map.of("q_hj1", new double[] {0, 0}, "q_hj2", new double[] {0, 0});

    /** A perception of an upright T1 at (x, y) facing yaw (world), optionally seeing the ball straight ahead at d. */
    static MjPerception at(double t, String mode, double x, double y, double yawDeg, double ballDistance) {
        double h = Math.toRadians(yawDeg) / 2;
        List<MjPerception.Seen> seen = ballDistance > 0 ? List.of(new MjPerception.Seen("B", ballDistance, 0, 0)) : List.of();
        return new MjPerception(t, 0, mode, "Phalanx", "Other", 0, 0, new double[] {Math.cos(h), 0, 0, Math.sin(h)},
                new double[] {x, y, 0.67}, null, null, HEAD, Map.of(), seen, List.of(), 0);
    }

    @Test
    void beamsToItsKickOffSpotOnceASecondUntilThere() {
        MjBehaviour b = new MjBehaviour(MjField.SSIM, 3, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(10, "BeforeKickOff", -3, 21, -90, 0));
        Pose2 spot = b.kickOffSpot();
        assertEquals(spot, b.decide(w).beam());
        w.update(at(10.02, "BeforeKickOff", -3, 21, -90, 0));
        assertNull(b.decide(w).beam(), "not again within a second");
        w.update(at(11.1, "BeforeKickOff", -3, 21, -90, 0));
        assertEquals(spot, b.decide(w).beam(), "refused or not yet there: again");
        w.update(at(12.2, "BeforeKickOff", spot.x() + 0.05, spot.y(), 0, 0));
        assertSame(MjBehaviour.Intent.STAND, b.decide(w), "there: stand");
    }

    @Test
    void inPlayOnTheForwardWalksAtTheBallAndTurnsFirstWhenItIsBehind() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        assertEquals(Role.FC, fc.role());
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -5, 0, 0, 4));            // ball 4 m ahead
        MjBehaviour.Intent i = fc.decide(w);
        assertTrue(i.vx() > 0 && Math.abs(i.turnDegPerS()) < 5, "walks straight at it: " + i);
        w.update(at(1.1, "PlayOn", -5, 0, 180, 0));        // now facing away; ball still remembered at (-0.9.., 0)
        i = fc.decide(w);
        assertEquals(0, i.vx(), 1e-9, "turns in place first: " + i);
        assertEquals(MjBehaviour.Config.DEFAULT.maxTurn(), Math.abs(i.turnDegPerS()), 1e-9);
    }

    /** Where the torso stands to kick the ball at {@code ball} to the goal (+x) with the foot: the kick window's centre. */
    private static Pose2 kickPose(MjBehaviour.Config c, Vector2 ball, MjBehaviour.Foot foot) {
        double side = foot == MjBehaviour.Foot.LEFT ? 1 : -1, theta = side * c.kickDirectionDeg();
        Vector2 p = ball.minus(new Vector2(c.kickBallX() + c.kickBackoffM() / 2, side * c.kickBallY()).rotate(theta));
        return new Pose2(p.x(), p.y(), theta);
    }

    @Test
    void closeBehindTheBallAndFacingTheGoalItKicksWithTheFootOnTheBallsSide() {
        MjBehaviour.Config c = MjBehaviour.Config.DEFAULT;
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, c);
        Vector2 ball = new Vector2(0, 0);   // the goal is at +x, straight ahead
        Pose2 right = kickPose(c, ball, MjBehaviour.Foot.RIGHT), left = kickPose(c, ball, MjBehaviour.Foot.LEFT);
        assertEquals(MjBehaviour.Foot.RIGHT, fc.kickToGoal(right, ball).kick());
        assertEquals(MjBehaviour.Foot.LEFT, fc.kickToGoal(left, ball).kick());
        assertEquals(MjBehaviour.Foot.RIGHT, fc.kickToGoal(new Pose2(right.x() + 0.02, right.y() - 0.02, right.thetaDeg() + 5), ball).kick(),
                "within the tolerance");
        MjBehaviour.Intent offAim = fc.kickToGoal(new Pose2(right.x(), right.y(), right.thetaDeg() + 40), ball);
        assertNull(offAim.kick(), "facing 40 deg off: no kick");
        assertTrue(offAim.turnDegPerS() < 0, "turns back: " + offAim);
        MjBehaviour.Intent far = fc.kickToGoal(new Pose2(-3, 0.5, 0), ball);
        assertNull(far.kick());
        assertTrue(far.vx() > 0, "walks to the spot behind the ball: " + far);
        MjBehaviour.Intent near = fc.kickToGoal(new Pose2(right.x() - 0.3, right.y(), right.thetaDeg()), ball);
        assertNull(near.kick());
        assertTrue(near.vx() > 0 && near.vx() <= c.fineSpeed(), "steps up to it slowly: " + near);
        // the spot lies on the ball-to-goal line: the same offsets beside a ball far out on the wing are no kick
        Vector2 wide = new Vector2(20, 12);
        assertNull(fc.kickToGoal(new Pose2(wide.x() + right.x(), wide.y() + right.y(), right.thetaDeg()), wide).kick(),
                "the goal is 41 deg to the right of there");
    }

    @Test
    void itFacesOffTheGoalByTheKicksMeasuredDirection() {
        MjBehaviour.Config d = MjBehaviour.Config.DEFAULT;
        MjBehaviour.Config c = new MjBehaviour.Config(d.maxForward(), d.maxTurn(), d.turnFirstDeg(), d.arriveM(), d.beamToleranceM(),
                d.beamRepeatS(), d.kickBallX(), d.kickBallY(), -30, d.kickBackoffM(), d.kickToleranceM(), d.kickAimDeg(), d.approachM(),
                d.fineSpeed());
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, c);
        Vector2 ball = new Vector2(0, 0);
        Pose2 right = kickPose(c, ball, MjBehaviour.Foot.RIGHT);
        assertEquals(30, right.thetaDeg(), 1e-9, "the right foot sends it 30 deg right: face 30 deg left");
        assertEquals(MjBehaviour.Foot.RIGHT, fc.kickToGoal(right, ball).kick());
        assertNull(fc.kickToGoal(new Pose2(right.x(), right.y(), 0), ball).kick(), "facing the goal itself: no kick");
        assertEquals(-30, kickPose(c, ball, MjBehaviour.Foot.LEFT).thetaDeg(), 1e-9);
        assertEquals(MjBehaviour.Foot.LEFT, fc.kickToGoal(kickPose(c, ball, MjBehaviour.Foot.LEFT), ball).kick());
    }

    @Test
    void inFrontOfTheBallItWalksRoundItNotThroughIt() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjBehaviour.Intent i = fc.kickToGoal(new Pose2(0.6, 0, 180), new Vector2(0, 0));   // between the ball and the goal, facing it
        assertNull(i.kick());
        assertTrue(Math.abs(i.turnDegPerS()) > 10, "heads off to one side of the ball: " + i);
    }

    @Test
    void aDefenderWithoutABallInSightTurnsToLookForIt() {
        MjBehaviour dc = new MjBehaviour(MjField.SSIM, 3, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -20, 0, 0, 0));
        assertNotEquals(0, dc.decide(w).turnDegPerS());
        assertEquals(0, dc.decide(w).vx(), 1e-9);
    }

    @Test
    void ordersOnBallSendsADefenderToTheBallAndAnyOtherOrderKeepsTheNearestAway() {
        MjBehaviour dc = new MjBehaviour(MjField.SSIM, 3, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -10, 0, 0, 3));   // the ball 3 m ahead
        Pose2 self = w.self();
        Vector2 ball = w.ball();
        MjBehaviour.Intent toBall = dc.kickToGoal(self, ball), home = dc.decide(w, null, false);
        assertNotEquals(toBall, home, "the defender's spot is not the way to the ball");
        assertEquals(toBall, dc.decide(w, Action.of(3, ActionId.ON_BALL), false), "ordered On Ball: to the ball, nearest or not");
        assertEquals(toBall, dc.decide(w, null, true), "no order, nearest by the reports: to the ball (the rule without orders)");
        assertEquals(home, dc.decide(w, Action.of(3, ActionId.LOOK_STRAIGHT), true), "another order: its spot, even when nearest");
        assertEquals(home, dc.decide(w, Action.of(3, ActionId.TURN_TO_LOCALIZE), true));
        w.update(at(1.02, "KickOff_Right", -10, 0, 0, 3));
        assertEquals(dc.decide(w, null, false), dc.decide(w, Action.of(3, ActionId.ON_BALL), false), "not into their kick-off");
    }

    @Test
    void walkToCoordinateWalksToThePointAndThereFacesTheBall() {
        MjBehaviour.Config c = MjBehaviour.Config.DEFAULT;
        MjBehaviour dl = new MjBehaviour(MjField.SSIM, 2, c);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", 0, 0, 0, 0));   // no ball in sight: the order still leads
        MjBehaviour.Intent i = dl.decide(w, Action.walkTo(2, 10, 2, 0), true);
        // 11.3 deg off: below turnFirstDeg, so it walks at full speed turning toward the point
        assertEquals(c.maxForward(), i.vx(), 1e-9, "walks: " + i);
        assertEquals(Math.toDegrees(Math.atan2(2, 10)), i.turnDegPerS(), 1e-6);
        i = dl.decide(w, Action.walkTo(2, -20, 10, 0), true);
        assertEquals(0, i.vx(), 1e-9, "the point behind: turns first: " + i);
        assertEquals(c.maxTurn(), i.turnDegPerS(), 1e-9);
        // there (within arriveM): faces the order's heading without a ball, the ball once it sees one
        assertSame(MjBehaviour.Intent.STAND, dl.decide(w, Action.walkTo(2, 0.2, 0, 0), false), "facing 0 as ordered: stands");
        assertEquals(c.maxTurn(), dl.decide(w, Action.walkTo(2, 0.2, 0, 90), false).turnDegPerS(), 1e-9, "turns to face 90");
        w.update(at(1.02, "PlayOn", 0, 0, 0, 3));
        assertSame(MjBehaviour.Intent.STAND, dl.decide(w, Action.walkTo(2, 0.2, 0, 90), false), "the ball ahead: faces it, stands");
    }

    /** {@code p} with another play time (GS t). */
    private static MjPerception withGameTime(MjPerception p, double gameTime) {
        return new MjPerception(p.time(), gameTime, p.playMode(), p.teamLeft(), p.teamRight(), 0, 0, p.quat(), p.pos(), p.gyro(), p.acc(),
                p.joints(), p.touch(), p.seen(), p.heard(), p.heardSkipped());
    }

    @Test
    void beforeTheirKickOffItBeamsOutOfTheCentreCircle() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        Pose2 ours = fc.kickOffSpot(), theirs = fc.kickOffSpot(true);
        assertEquals(-1.1, ours.x(), 0.05, "our kick-off: the formation's forward spot behind the ball");
        assertTrue(theirs.position().norm() >= 6.5 - 1e-9 && theirs.x() <= -1, "theirs: out of the circle and their half: " + theirs);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(10, "BeforeKickOff", -3, 21, -90, 0));
        assertEquals(ours, fc.decide(w).beam(), "the first half: the left team kicks off");
        MjBehaviour fc2 = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjWorld second = new MjWorld("Phalanx");
        second.update(withGameTime(at(10, "BeforeKickOff", -3, 21, -90, 0), 300));
        assertEquals(theirs, fc2.decide(second).beam(), "the second half: the right team kicks off");
        MjBehaviour fc3 = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjWorld goal = new MjWorld("Phalanx");
        goal.update(at(10, "Goal_Left", -3, 21, -90, 0));
        assertEquals(theirs, fc3.decide(goal).beam(), "after our goal they kick off");
        MjBehaviour fc4 = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjWorld conceded = new MjWorld("Phalanx");
        conceded.update(at(10, "Goal_Right", -3, 21, -90, 0));
        assertEquals(ours, fc4.decide(conceded).beam(), "after theirs we do");
    }

    @Test
    void inTheirSetPieceNobodyGoesToTheBallAndEveryWalkKeepsOutOfTheCircle() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "free_kick_right", -10, 0, 0, 3));   // the ball 3 m ahead, at about (-6.9, 0)
        MjBehaviour.Intent i = fc.decide(w, Action.of(7, ActionId.ON_BALL), true);
        assertNull(i.kick());
        // its place: on the ball's line to our goal 6.5 m from it, about (-13.4, 0): behind it, so it turns
        assertEquals(0, i.vx(), 1e-9, "not toward the ball: " + i);
        assertEquals(MjBehaviour.Config.DEFAULT.maxTurn(), Math.abs(i.turnDegPerS()), 1e-9);
        MjWorld ours = new MjWorld("Phalanx");
        ours.update(at(1, "free_kick_left", -10, 0, 0, 3));
        assertEquals(fc.kickToGoal(ours.self(), ours.ball()), fc.decide(ours, Action.of(7, ActionId.ON_BALL), true), "our own: the taker goes");
        // an order into the circle: to the nearest place outside it, round the circle
        Vector2 ball = w.ball();
        MjSetPiece rules = MjSetPiece.of("free_kick_right", 1, MjField.SSIM, ball, false, MjSetPiece.Config.DEFAULT);
        Vector2 via = rules.via(w.self().position(), rules.allowed(new Vector2(-6, 1), MjField.SSIM), MjSetPiece.Config.DEFAULT);
        assertTrue(via.distanceTo(ball) > 6.5, "a waypoint round the circle: " + via);
        MjWorld play = new MjWorld("Phalanx");
        play.update(at(1, "PlayOn", -10, 0, 0, 3));
        assertEquals(fc.decide(play, Action.walkTo(7, via.x(), via.y(), 0), false), fc.decide(w, Action.walkTo(7, -6, 1, 0), false));
        MjWorld kickOff = new MjWorld("Phalanx");
        kickOff.update(at(1, "KickOff_Right", -3, 0, 0, 3));   // inside the circle: out, away from the ball
        MjBehaviour.Intent out = fc.decide(kickOff, null, true);
        assertTrue(out.vx() == 0 && out.turnDegPerS() != 0, "turns to walk back out: " + out);
        MjWorld crept = new MjWorld("Phalanx");
        crept.update(at(1, "KickOff_Right", -6.2, 0, 0, 0));   // the ball on the centre spot (the kick-off's drop), its place (-6.5, 0) 0.3 m behind
        MjBehaviour.Intent hold = fc.decide(crept, null, true);
        assertTrue(hold.vx() < 0 && Math.abs(hold.turnDegPerS()) < 5, "steps back facing the ball, no turning round: " + hold);
        MjWorld held = new MjWorld("Phalanx");
        held.update(at(1, "KickOff_Right", -6.45, 0, 0, 0));
        assertSame(MjBehaviour.Intent.STAND, fc.decide(held, null, true), "within 0.1 m: stands");
    }

    @Test
    void aPlayerBarredByTheDoubleTouchRuleKeepsOffTheBallWhateverItIsOrdered() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -0.5, 0, 0, 0.4));   // at the ball, facing it
        Action onBall = Action.of(7, ActionId.ON_BALL);
        assertEquals(fc.kickToGoal(w.self(), w.ball()), fc.decide(w, onBall, true, false));
        MjBehaviour.Intent i = fc.decide(w, onBall, true, true);
        assertNull(i.kick());
        assertNotEquals(fc.kickToGoal(w.self(), w.ball()), i);
        assertTrue(i.vx() < 0 && i.vy() > 0 && i.turnDegPerS() == 0, "steps back and to the left off the ball ahead, not turning: " + i);
        w.update(at(1.01, "PlayOn", -0.5, 0, -20, 0));   // turned 20 deg right: the ball (not seen again) 20 deg to its left
        MjBehaviour.Intent right = fc.decide(w, onBall, true, true);
        assertTrue(right.vx() < 0 && right.vy() < 0 && right.turnDegPerS() == 0, "to the right, away from it: " + right);
        w.update(at(1.02, "PlayOn", -2.3, 0, 0, 2.2));
        MjBehaviour.Intent away = fc.decide(w, onBall, true, true);
        MjBehaviour.Intent spot = fc.decide(w, Action.of(7, ActionId.LOOK_STRAIGHT), false, false);
        assertTrue(spot.vx() == MjBehaviour.Config.DEFAULT.maxForward(), "unbarred, its formation spot 1.1 m behind the ball: walks up: " + spot);
        assertTrue(away.vx() > 0 && away.vx() <= MjBehaviour.Config.DEFAULT.fineSpeed() + 1e-9,
                "barred, the same spot held 2 m off the ball: small steps up to there: " + away);
        w.update(at(1.04, "PlayOn", -2.05, 0, 0, 1.95));
        assertTrue(fc.decide(w, onBall, true, true).vx() < 0.1, "at 2 m: no further");
    }
}

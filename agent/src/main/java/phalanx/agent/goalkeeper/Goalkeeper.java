package phalanx.agent.goalkeeper;

import phalanx.agent.AgentConfig;
import phalanx.agent.action.ApproachBall;
import phalanx.agent.action.ChargingGuard;
import phalanx.agent.action.Facts;
import phalanx.agent.action.OnBall;
import phalanx.agent.action.TrackMovingObject;
import phalanx.agent.action.WalkToCoordinate;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * The goalkeeper's own behaviour, the finite state machine of thesis 5.13 (Figure 5.14):
 * <pre>
 * LOCALIZE  walk to the guard spot between the posts, facing the field      -> GUARD when there
 * GUARD     track the moving ball, stand on its line to the goal's centre;
 *           dive when it will cross the goal mouth                           -> DIVING
 *           within the dive time; ball (still) in the goal area, nobody near -> LIBERO
 *           pushed off the spot (and no shot coming)                         -> LOCALIZE
 *           ball within challengeDepth of our goal line, in front of the goal -> CHALLENGE
 * LIBERO    On Ball: clear the ball out of the goal area                     -> LOCALIZE when cleared or lost
 * CHALLENGE walk through the ball from the goal's side, pushing it away        -> LOCALIZE when out of the box
 * DIVING    the dive plays to its end (the behaviour stands up afterwards)   -> LOCALIZE
 * </pre>
 * Ours beyond the thesis: a shot is also dived for in LOCALIZE and LIBERO while near the spot;
 * Libero waits for a (nearly) still ball; DIVING is a state of its own so nothing interrupts the dive;
 * a ball pushed along by a nearby opponent is not dived for unless it is shot (AgentConfig.Keeper.shotSpeed);
 * Guard side-steps to keep on the line from the goal's centre to the ball (AgentConfig.Keeper.maxShift), and steps back
 * to the spot's depth when more than 0.2 m off it;
 * Challenge (issue 18) comes out for a ball near the goal instead of waiting on the line for the shot.
 */
public final class Goalkeeper implements Action {
    public enum State { LOCALIZE, GUARD, LIBERO, DIVING, CHALLENGE }

    private final AgentConfig config;
    private final TrackMovingObject track;
    private final Dive dive;
    /** The approach's omnidirectional walk that keeps the given heading (backpedal). */
    private final AgentConfig.Approach backwards;
    private WalkToCoordinate toSpot;
    private WalkToCoordinate toBall;
    private OnBall libero;
    private State state = State.LOCALIZE;
    private boolean shifting;
    private boolean onDepth = true;

    public Goalkeeper(AgentConfig config) {
        this.config = config;
        AgentConfig.Approach a = config.approach();
        // faceWayBeyond infinite: the walk keeps the heading given and steps toward the point whatever its bearing
        this.backwards = new AgentConfig.Approach(a.enabled(), a.behind(), a.sideClearance(), a.slowWithin(),
                a.minShare(), Double.POSITIVE_INFINITY, a.turnFullDeg(), a.arriveDistance(), a.arriveDeg());
        this.track = new TrackMovingObject(config);
        this.dive = new Dive(config);
    }

    public State state() { return state; }

    /** True while it is clearing the ball (Libero): the coordination's Support mode (5.2, 5.13). */
    public boolean hasBall() { return state == State.LIBERO; }

    /** True while a dive is requested or playing: nothing may interrupt it, not even Stand Up. */
    public boolean diving() { return state == State.DIVING; }

    @Override
    public Decision decide(Situation s) {
        return switch (state) {
            case LOCALIZE -> localize(s);
            case GUARD -> guard(s);
            case LIBERO -> libero(s);
            case DIVING -> diving(s);
            case CHALLENGE -> challenge(s);
        };
    }

    private Decision localize(Situation s) {
        WalkToCoordinate walk = walkToSpot(s);
        if (nearSpot(s)) {
            Decision d = tryDive(s);
            if (d != null) return d;
        }
        if (inChallengeBox(s, 0)) {
            state = State.CHALLENGE;
            return challenge(s);
        }
        if (walk.done(s)) {
            state = State.GUARD;
            return guard(s);
        }
        Move back = backpedal(s);
        return back != null ? Decision.of(back, track.head(s)) : walk.decide(s);
    }

    /**
     * Back to the spot from the field's side of it, within BACKPEDAL_WITHIN: the omnidirectional walk straight backwards,
     * facing away from the spot (so the field), with the head on the ball; null otherwise. Walk To Coordinate turned the
     * keeper to face its own goal for the way back: in session 25's FCP game four of the six goals were shot while it
     * walked back from a Challenge or was turning round (its heading -119 to -136 and 142-148 degrees at the shots).
     */
    private Move backpedal(Situation s) {
        Pose2 self = Facts.self(s, config);
        if (self == null || s.field() == null) return null;
        Vector2 spot = spot(s.field());
        Vector2 away = self.position().minus(spot);
        double d = away.norm();
        if (d <= config.walk().positionTolerance() || d > BACKPEDAL_WITHIN || Math.abs(away.angleDeg()) > BACKPEDAL_MAX_DEG) return null;
        return ApproachBall.toward(self, new Pose2(spot.x(), spot.y(), away.angleDeg()), backwards);
    }

    /** The keeper walks backwards to its spot from at most this far, m (the Challenge goes at most ~3 m out). */
    private static final double BACKPEDAL_WITHIN = 3.0;
    /** ... and only from the field's side of the spot: within this of straight out from it, degrees. */
    private static final double BACKPEDAL_MAX_DEG = 80;

    private Decision guard(Situation s) {
        Decision d = tryDive(s);
        if (d != null) return d;
        if (liberoChance(s)) {
            state = State.LIBERO;
            libero = new OnBall(config);
            return libero.decide(s);
        }
        if (inChallengeBox(s, 0)) {
            state = State.CHALLENGE;
            return challenge(s);
        }
        if (!nearSpot(s)) {
            state = State.LOCALIZE;
            shifting = false;
            return walkToSpot(s).decide(s);
        }
        return Decision.of(shift(s), track.head(s));
    }

    /**
     * Guard's footwork: a side step toward the point of the spot's line (x = spot) that lies between the
     * goal's centre and the ball, at most maxShift from the middle; stand once within a third of the
     * tolerance of it (hysteresis, so the keeper does not dither).
     */
    private Move shift(Situation s) {
        AgentConfig.Keeper k = config.keeper();
        Pose2 self = Facts.self(s, config);
        Vector2 ball = Facts.ballGlobal(s, config);
        if (self == null || ball == null || s.field() == null || k.maxShift() <= 0) { shifting = false; return Move.STAND; }
        double goalX = -s.field().halfLength();
        double y = guardPoint(goalX, k.spotOffset(), k.maxShift(), ball).y();
        // Off the spot's line by more than DEPTH_TOLERANCE (side steps drift back): step back onto it, facing the field.
        // In session 23 the keeper stood on its goal line, 0.5 m behind the spot, for most of some halves, and two of
        // UT Austin Villa's goals went in from 3.5-4 m past it there.
        double spotX = goalX + k.spotOffset();
        onDepth = Math.abs(self.x() - spotX) <= (onDepth ? DEPTH_TOLERANCE : DEPTH_TOLERANCE / 3);
        if (!onDepth) { shifting = false; return ApproachBall.toward(self, new Pose2(spotX, y, 0), config.approach()); }
        double side = self.toRelative(new Vector2(spotX, y)).y();   // + = to the keeper's left
        double limit = shifting ? k.shiftTolerance() / 3 : k.shiftTolerance();
        shifting = Math.abs(side) > limit;
        return shifting ? new Move.SideStep(side > 0) : Move.STAND;
    }

    /**
     * Guard's place (thesis 5.13): the point of the spot's line (spotOffset in front of the goal line at goalX) that lies
     * between the goal's centre and the ball, at most maxShift from the middle; a ball level with the spot or behind it
     * puts the point at the post's side. Shared with the T1 keeper on rcssservermj ({@code agent/mj/MjKeeper}).
     */
    public static Vector2 guardPoint(double goalX, double spotOffset, double maxShift, Vector2 ball) {
        double depth = ball.x() - goalX;
        double y = depth <= spotOffset ? Math.signum(ball.y()) * maxShift : ball.y() * spotOffset / depth;
        return new Vector2(goalX + spotOffset, Math.max(-maxShift, Math.min(maxShift, y)));
    }

    private Decision libero(Situation s) {
        if (nearSpot(s)) {
            Decision d = tryDive(s);
            if (d != null) { libero = null; return d; }
        }
        Vector2 ball = Facts.ballGlobal(s, config);
        if (ball == null || cleared(s.field(), ball)) {
            state = State.LOCALIZE;
            libero = null;
            return walkToSpot(s).decide(s);
        }
        return libero.decide(s);
    }

    /**
     * Challenge: to the point challengePush past the ball on the line from our goal's centre through it, facing
     * along that line; a shot is still dived for. Back to Localize once the ball is out of the box by challengeExit.
     */
    private Decision challenge(Situation s) {
        Decision d = tryDive(s);
        if (d != null) { toBall = null; return d; }
        Vector2 ball = Facts.ballGlobal(s, config);
        if (ball == null || s.field() == null || !inChallengeBox(s, config.keeper().challengeExit())) {
            state = State.LOCALIZE;
            toBall = null;
            return walkToSpot(s).decide(s);
        }
        Vector2 out = ball.minus(new Vector2(-s.field().halfLength(), 0));
        double n = out.norm();
        Vector2 u = n < 1e-6 ? new Vector2(1, 0) : out.times(1 / n);
        Vector2 past = ball.plus(u.times(config.keeper().challengePush()));
        double outside = config.keeper().challengeOutside();
        // A ball just outside the area is gone for (walking slowly out there, below); farther out the keeper stops inside.
        boolean goesOut = outside > 0 && inGoalArea(s.field(), ball, outside) && !inGoalArea(s.field(), past, -AREA_MARGIN);
        Pose2 self = Facts.self(s, config);
        Vector2 to = clampToOwnArea(s.field(), self == null ? past : roundTheBall(self.position(), ball, u, past), goesOut ? outside + AREA_MARGIN : -AREA_MARGIN);
        challengeTarget = to;
        if (toBall == null) toBall = new WalkToCoordinate(config, to.x(), to.y(), u.angleDeg());
        else toBall.target(to.x(), to.y(), u.angleDeg());
        Decision walk = toBall.decide(s);
        // Without a self pose the walk turns to localize, and its head must pan for landmarks, not track the ball:
        // in session 20's g1 the keeper challenged 17.5 s with no self pose, the ball 1.3 m away, and the goal came from there.
        if (self == null) return walk;
        // Near its point it steps there facing the push, never "arrived" short of it (Walk To Coordinate's 0.25 m, 0.5 m
        // once there): in session 22's g8 (392-405 s) it stood 0.2-0.4 m from a ball just outside its area, 0.28 m from
        // the point behind it, for 9 s until UT Austin Villa shot past it. A tighter tolerance for the walk instead
        // turned the keeper round to walk back a few cm (session 23, g3).
        double toGo = to.distanceTo(self.position());
        if (toGo <= CHALLENGE_STEP_WITHIN && toGo > CHALLENGE_THERE)
            walk = Decision.of(ApproachBall.toward(self, new Pose2(to.x(), to.y(), u.angleDeg()), config.approach()), walk.head());
        // Going out, it is under the charging speed before it leaves the area (the walk needs ~0.4 m to slow down).
        boolean slow = goesOut && !inGoalArea(s.field(), self.position(), -SLOW_BEFORE_EDGE);
        return Decision.of(slow ? ChargingGuard.belowChargingSpeed(walk.move(), config.charging()) : walk.move(), track.head(s));
    }

    /**
     * Where the Challenge walks: through the ball (past) only from the goal's side of it, near the push line. A keeper
     * beyond the ball along the push direction u first goes round it, to its flank (ROUND_SIDE to the keeper's side of the
     * line); one level with it, or behind but off the line, first to the point ROUND_BEHIND on the goal's side. In session 21's g1 (C1, 427 s) the ball lay 8 s on
     * our goal line behind the keeper, which walked to the point past it, beside the ball, and stood; an opponent
     * walked it in.
     */
    private static Vector2 roundTheBall(Vector2 self, Vector2 ball, Vector2 u, Vector2 past) {
        Vector2 d = self.minus(ball);
        Vector2 perp = new Vector2(-u.y(), u.x());
        double along = d.x() * u.x() + d.y() * u.y(), lateral = d.x() * perp.x() + d.y() * perp.y();
        // Behind the ball within a cone about the push line: walking to "past" meets the ball.
        if (along <= -ROUND_BEHIND_OK && Math.abs(lateral) <= Math.max(ROUND_LATERAL_OK, -along * ROUND_CONE_SLOPE)) return past;
        if (along > 0) return ball.plus(perp.times(Math.copySign(ROUND_SIDE, lateral))).minus(u.times(ROUND_BEHIND_OK));
        return ball.minus(u.times(ROUND_BEHIND));
    }

    /** The last point the Challenge walked to (tests). */
    Vector2 challengeTarget() { return challengeTarget; }

    private Vector2 challengeTarget;
    /** On the goal's side of the ball by this much along the push, the keeper walks through it, m. */
    private static final double ROUND_BEHIND_OK = 0.1;
    /** Behind the ball, the keeper walks through it when this close to the push line, m, ... */
    private static final double ROUND_LATERAL_OK = 0.15;
    /** ... or within this slope of it (tan 35°: farther back it may be farther to the side). */
    private static final double ROUND_CONE_SLOPE = 0.7;
    /** Going round: the flank this far to the side of the ball (torso half-width and the ball's radius, with room), m. */
    private static final double ROUND_SIDE = 0.35;
    /** Going round: then this far behind the ball on the goal's side, m. */
    private static final double ROUND_BEHIND = 0.3;

    /** Guard holds the spot's depth within this, m; once it steps back onto it, within a third of it. */
    private static final double DEPTH_TOLERANCE = 0.2;

    /** Within this of its point the Challenge side-steps there with the omnidirectional walk, m ... */
    private static final double CHALLENGE_STEP_WITHIN = 0.6;
    /** ... until this near it, m. */
    private static final double CHALLENGE_THERE = 0.05;

    /** How far inside its penalty area's edges the keeper's Challenge stops. */
    private static final double AREA_MARGIN = 0.15;
    /** Going out of the area, the keeper walks under the charging speed from this far inside its edge on, m. */
    private static final double SLOW_BEFORE_EDGE = 0.4;

    /**
     * The point moved inside our penalty area grown by a margin (negative: AREA_MARGIN inside it). The server's charging
     * rule spares a goalie only inside its own penalty area (SimSpark soccerruleaspect.cpp, AnalyseChargingFouls): in
     * g20b the keeper met an opponent at the ball 2.7 m out, was taken off to the touch line (377 s) and the goal fell
     * while it walked back.
     */
    private static Vector2 clampToOwnArea(FieldSpec f, Vector2 p, double margin) {
        double maxX = -f.halfLength() + f.penaltyDepth() + margin, maxY = f.penaltyWidth() / 2 + margin;
        return new Vector2(Math.min(p.x(), maxX), Math.max(-maxY, Math.min(maxY, p.y())));
    }

    /** The ball (believed, field frame) in front of our goal line, within challengeDepth of it and challengeWidth of the middle, grown by a margin. */
    private boolean inChallengeBox(Situation s, double margin) {
        AgentConfig.Keeper k = config.keeper();
        if (k.challengeDepth() <= 0 || s.field() == null) return false;
        Vector2 ball = Facts.ballGlobal(s, config);
        if (ball == null) return false;
        double depth = ball.x() + s.field().halfLength();
        return depth >= 0 && depth <= k.challengeDepth() + margin && Math.abs(ball.y()) <= k.challengeWidth() + margin;
    }

    private Decision diving(Situation s) {
        Decision d = dive.decide(s);
        if (dive.done(s)) {
            state = State.LOCALIZE;
            return Decision.of(Move.STAND, track.head(s));
        }
        return d;
    }

    /** Starts a dive when a shot will cross the goal mouth within the dive time; null when none. */
    private Decision tryDive(Situation s) {
        Boolean left = shotSide(s);
        if (left == null) return null;
        state = State.DIVING;
        dive.start(s, left);
        return dive.decide(s);
    }

    /**
     * Thesis 5.13, Guard: where the ball's path crosses our Y axis; when that point lies between
     * Threshold_Right and Threshold_Left (the goal mouth plus a margin) and the rolling ball gets
     * there within the dive time, dive to its side. Null for no dive (no ball, too slow, wide,
     * not yet, or straight at the body).
     */
    Boolean shotSide(Situation s) {
        Vector2 ball = Facts.ball(s, config);
        Vector2 v = track.relativeVelocity(s);
        AgentConfig.Keeper k = config.keeper();
        if (ball == null || v == null || v.norm() < k.minApproachSpeed() || ball.norm() < k.minDiveDistance()) return null;
        if (v.norm() < k.shotSpeed() && opponentNearBall(s)) return null;     // pushed along, not shot: the body blocks
        BallRoll.Crossing c = BallRoll.crossing(ball, v, k.ballDecay());
        if (c == null || c.seconds() > k.diveSeconds()) return null;
        if (!insideThresholds(s, c.lateral()) || Math.abs(c.lateral()) <= k.bodyBlock()) return null;
        return c.lateral() > 0;
    }

    /** Threshold_Left/Right: the crossing point, put in the own frame, lies within the goal mouth plus the margin. */
    private boolean insideThresholds(Situation s, double lateral) {
        double half = (s.field() == null ? FieldSpec.V066 : s.field()).goalWidth() / 2 + config.keeper().postMargin();
        Pose2 self = Facts.self(s, config);
        if (self == null) return Math.abs(lateral) <= half;     // egocentric: assume we stand in the goal's middle
        return Math.abs(self.toGlobal(new Vector2(0, lateral)).y()) <= half;
    }

    /** Libero: the ball inside our goal area, (nearly) still, and no other player near it. */
    private boolean liberoChance(Situation s) {
        if (!config.keeper().libero()) return false;
        Vector2 ball = Facts.ballGlobal(s, config);
        if (ball == null || s.field() == null || !inGoalArea(s.field(), ball, 0)) return false;
        Vector2 v = Facts.ballVelocity(s);
        if (v != null && v.norm() >= config.keeper().liberoMaxSpeed()) return false;
        WorldBelief b = s.belief();
        return !anyoneNear(b.teammates(), b.time(), ball) && !anyoneNear(b.opponents(), b.time(), ball);
    }

    private boolean opponentNearBall(Situation s) {
        Vector2 ball = Facts.ballGlobal(s, config);
        return Facts.opponentNear(s, config, ball, config.keeper().dribbleDistance());
    }

    private boolean anyoneNear(List<PlayerBelief> players, double now, Vector2 ball) {
        return Facts.anyoneNear(players, now, ball, config.keeper().liberoClearance(), config);
    }

    private boolean cleared(FieldSpec f, Vector2 ball) {
        return f == null || !inGoalArea(f, ball, config.keeper().liberoExitMargin());
    }

    /**
     * Inside our goal area (the field's penalty box: 1.8 m deep, 3.9 m wide on 0.6.6+; on rcssservermj's field,
     * {@code MjField.spec()}, its penalty area, 9 x 16.5 m), grown by a margin.
     */
    public static boolean inGoalArea(FieldSpec f, Vector2 p, double margin) {
        return p.x() <= -f.halfLength() + f.penaltyDepth() + margin && p.x() >= -f.halfLength() - margin
                && Math.abs(p.y()) <= f.penaltyWidth() / 2 + margin;
    }

    private boolean nearSpot(Situation s) {
        Pose2 self = Facts.self(s, config);
        return self != null && s.field() != null
                && self.position().distanceTo(spot(s.field())) <= config.keeper().relocalizeDistance();
    }

    private Vector2 spot(FieldSpec f) { return new Vector2(-f.halfLength() + config.keeper().spotOffset(), 0); }

    private WalkToCoordinate walkToSpot(Situation s) {
        Vector2 p = spot(s.field() == null ? FieldSpec.V066 : s.field());
        if (toSpot == null) toSpot = new WalkToCoordinate(config, p.x(), p.y(), 0);
        else toSpot.target(p.x(), p.y(), 0);
        return toSpot;
    }
}

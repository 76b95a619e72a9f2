package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.HeadTarget;
import phalanx.agent.decide.Move;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.ActionId;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.fall.FallState;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.Locale;
import java.util.logging.Logger;

/**
 * A field player's decisions each cycle. Stand Up comes first whenever the robot is down (and it
 * waits while it is only falling). Otherwise it runs the coordinator's last order (thesis 5.3:
 * one action, executed until the next one; ours: an On Ball player with the ball within
 * {@code fallback.keepBallWithin} keeps On Ball until the ball is farther), or, when there is none or the coordinator has gone
 * quiet, its own choice (the kick-off's taker and partner excepted, {@link KickOffPlay}):
 * <ul>
 *   <li>On Ball when the ball is known, within {@code fallback.onBallDistance}, and no teammate
 *       seen within the memory time is closer to it (once on the ball, a teammate must be closer
 *       by {@code fallback.hysteresis} to take over): every player that believes itself nearest
 *       goes, which at worst sends two, never none;</li>
 *   <li>else Walk To Coordinate to the home position the caller gives (its formation spot),
 *       facing the ball (or the opponent's goal when the ball is unknown);</li>
 *   <li>without a home position, Turn To Ball, or Look For Ball when the ball is unknown.</li>
 * </ul>
 * This is the fallback {@code comm.team.round.FieldPlayerRounds} describes. The action instance is kept while
 * the order's action id stays the same (new coordinates or directions retarget it), so On Ball's
 * state machine survives the coordinator repeating the order every round.
 */
public final class FieldPlayerBehaviour {
    private static final Logger LOG = Logger.getLogger(FieldPlayerBehaviour.class.getName());
    private final AgentConfig config;
    private final StandUp standUp;
    private final KickOffPlay kickOff;
    private final ChargingGuard guard;
    private final TheirSetPiece theirSetPiece;
    private phalanx.comm.team.Action order;
    private ActionId runningId;
    private boolean runningOwn;
    private Action running;
    private Action lastAction;
    private Object lastPhase;
    private boolean lastOrdered;

    /** A player with no part in our kick-off. */
    public FieldPlayerBehaviour(AgentConfig config) { this(config, 0); }

    /** Player {@code unum}: the kick-off's taker and partner ({@link KickOffPlay}) are chosen by number. */
    public FieldPlayerBehaviour(AgentConfig config, int unum) {
        this.config = config;
        this.standUp = new StandUp(config);
        this.kickOff = new KickOffPlay(config, unum);
        this.guard = new ChargingGuard(config);
        this.theirSetPiece = new TheirSetPiece(config);
    }

    /** The coordinator's last order to this player (null: none). */
    public void order(phalanx.comm.team.Action a) { order = a; }

    public phalanx.comm.team.Action order() { return order; }

    /** The action run in the last cycle (null before the first), for logs and tests. */
    public Action running() { return running; }

    /**
     * One cycle.
     *
     * @param coordinatorQuiet the team channel says the coordinator has gone quiet
     * @param home             the own-frame home position for the fallback (null: none)
     */
    public Decision decide(Situation s, boolean coordinatorQuiet, Vector2 home) {
        FallState f = Facts.fall(s);
        if (f.isDown() || standUp.busy()) return standUp.decide(s);
        if (f == FallState.FALLING) return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
        if (s.playMode() == PlayMode.GAME_OVER) return Decision.of(Move.STAND, HeadTarget.STRAIGHT);
        Decision k = kickOff.decide(s);
        if (k != null) return k;
        if (order != null && !coordinatorQuiet) {
            if (!keepsTheBall(s, order)) running = ordered(order);
            runningOwn = false;
        } else {
            running = ownChoice(s, home);
            runningOwn = true;
        }
        Action act = theirSetPiece.adjust(s, running);
        Decision chosen = act.decide(s);
        Decision d = guard.apply(s, chosen);
        logPhase(s, act != running);
        if (LOG.isLoggable(java.util.logging.Level.FINE)) trace(s, chosen, d);
        return d;
    }

    /**
     * At FINE (off by default; a logging config sets this class to FINE, agent/README.md "Reading a game's player logs"): On Ball's state, the move and
     * whether the charging guard slowed it, the ball and the nearest opponent (own frame), ten times a game second.
     * For a match review of a player near the ball that does not get to it; nothing is built otherwise.
     */
    private void trace(Situation s, Decision chosen, Decision d) {
        long tenth = (long) Math.floor(s.gameTime() * 10);
        if (tenth == lastTrace || !(running instanceof OnBall o)) return;
        lastTrace = tenth;
        Vector2 ball = Facts.ball(s, config);
        Pose2 self = Facts.self(s, config);
        Vector2 opp = null;
        WorldBelief b = s.belief();
        if (b != null && b.opponents() != null)
            for (PlayerBelief p : b.opponents()) {
                if (p == null || !(b.time() - p.time() <= config.beliefs().playerMemorySeconds())) continue;
                Vector2 r = Facts.relative(p, self);
                if (r != null && r.isFinite() && (opp == null || r.norm() < opp.norm())) opp = r;
            }
        LOG.fine(String.format(Locale.ROOT, "trace t=%.1f %s move=%s%s ball=%s opp=%s self=%s", s.gameTime(), o.state(), d.move(),
                d.move() != chosen.move() ? " (slowed)" : "", xy(ball), xy(opp),
                self == null ? "?" : String.format(Locale.ROOT, "(%.2f,%.2f,%.0f)", self.position().x(), self.position().y(), self.thetaDeg())));
    }

    private long lastTrace = Long.MIN_VALUE;

    private static String xy(Vector2 v) {
        return v == null ? "?" : String.format(Locale.ROOT, "(%.2f,%.2f)", v.x(), v.y());
    }

    /**
     * One log line when the action (or On Ball's state) changes, with who chose it: what a match review
     * needs to see why a player near the ball did not kick it. Nothing is built in an ordinary cycle.
     */
    private void logPhase(Situation s, boolean keptOut) {
        Object phase = keptOut ? "KEPT_OUT" : running instanceof OnBall o ? o.state() : null;
        if (running == lastAction && phase == lastPhase && runningOwn != lastOrdered) return;
        lastAction = running;
        lastPhase = phase;
        lastOrdered = !runningOwn;
        Vector2 ball = Facts.ball(s, config);
        LOG.info(String.format(Locale.ROOT, "action %s%s (%s) at game time %.2f ball=%s", running.getClass().getSimpleName(),
                phase == null ? "" : " " + phase, runningOwn ? "own" : "ordered", s.gameTime(),
                ball == null ? "?" : String.format(Locale.ROOT, "(%.2f,%.2f)", ball.x(), ball.y())));
    }

    /**
     * An ordered On Ball player with the ball within keepBallWithin keeps On Ball whatever the new order says,
     * until the ball is farther: the coordinator plans from reports a round old (AgentConfig.Fallback).
     */
    private boolean keepsTheBall(Situation s, phalanx.comm.team.Action next) {
        if (next.id() == ActionId.ON_BALL || runningOwn || !(running instanceof OnBall)) return false;
        Vector2 ball = Facts.ball(s, config);
        return ball != null && ball.norm() <= config.fallback().keepBallWithin();
    }

    /** The instance for an order: the running one when the id is unchanged, retargeted. */
    private Action ordered(phalanx.comm.team.Action a) {
        if (runningOwn || a.id() != runningId || running == null) {
            runningId = a.id();
            return create(a);
        }
        if (running instanceof WalkToCoordinate w) w.target(a.x(), a.y(), a.thetaDeg());
        else if (running instanceof WalkToDirection w) w.direction(a.thetaDeg());
        else if (running instanceof DribbleBallToDirection d) d.direction(a.thetaDeg());
        return running;
    }

    private Action create(phalanx.comm.team.Action a) {
        return switch (a.id()) {
            case LOOK_STRAIGHT -> new LookStraight();
            case LOOK_FOR_BALL -> new LookForBall(config);
            case TURN_TO_LOCALIZE -> new TurnToLocalize(config);
            case STAND_UP -> standUp;
            case TURN_TO_BALL -> new TurnToBall(config);
            case WALK_TO_BALL -> new WalkToBall(config);
            case ON_BALL -> new OnBall(config);
            case WALK_TO_COORDINATE -> new WalkToCoordinate(config, a.x(), a.y(), a.thetaDeg());
            case WALK_TO_DIRECTION -> new WalkToDirection(config, a.thetaDeg());
            case DRIBBLE_TO_DIRECTION -> new DribbleBallToDirection(config, a.thetaDeg());
            case FIND_OPPONENT_GOAL -> new FindOpponentGoal(config);
        };
    }

    private Action ownChoice(Situation s, Vector2 home) {
        boolean wasOnBall = runningOwn && running instanceof OnBall;
        runningId = null;
        if (shouldGoOnBall(s, wasOnBall)) return wasOnBall ? running : new OnBall(config);
        Vector2 ballGlobal = Facts.ballGlobal(s, config);
        if (home != null && home.isFinite()) {
            // Ours: at home with the ball unknown, look for it (turn and scan) rather than stand facing the goal
            // and pan: a ball behind stays out of a pan's view for good (session 19, the approach bench).
            if (ballGlobal == null && Facts.ball(s, config) == null && runningOwn
                    && (running instanceof LookForBall || running instanceof WalkToCoordinate w && w.done(s))) {
                return running instanceof LookForBall l ? l : new LookForBall(config);
            }
            Vector2 faceTo = ballGlobal != null ? ballGlobal : (s.field() == null ? null : s.field().opponentGoal());
            double theta = faceTo == null || faceTo.distanceTo(home) < 1e-6 ? 0 : faceTo.minus(home).angleDeg();
            if (runningOwn && running instanceof WalkToCoordinate w) {
                w.target(home.x(), home.y(), theta);
                return w;
            }
            return new WalkToCoordinate(config, home.x(), home.y(), theta);
        }
        if (Facts.ball(s, config) != null) return runningOwn && running instanceof TurnToBall t ? t : new TurnToBall(config);
        return runningOwn && running instanceof LookForBall l ? l : new LookForBall(config);
    }

    /** Ball near, and no teammate seen closer to it (by the hysteresis margin while already on it). */
    private boolean shouldGoOnBall(Situation s, boolean wasOnBall) {
        Vector2 ball = Facts.ball(s, config);
        if (ball == null) return false;
        double mine = ball.norm();
        if (mine > config.fallback().onBallDistance()) return false;
        double margin = wasOnBall ? config.fallback().hysteresis() : 0;
        return closestTeammate(s) >= mine - margin;
    }

    /** The smallest distance from a teammate seen within the memory time to the ball; infinite when none. */
    private double closestTeammate(Situation s) {
        WorldBelief b = s.belief();
        Vector2 ballGlobal = Facts.ballGlobal(s, config);
        Vector2 ballRel = Facts.ball(s, config);
        Pose2 self = Facts.self(s, config);
        double best = Double.POSITIVE_INFINITY;
        if (b == null || b.teammates() == null) return best;
        for (PlayerBelief p : b.teammates()) {
            if (p == null || !(b.time() - p.time() <= config.beliefs().playerMemorySeconds())) continue;
            double d;
            if (ballGlobal != null && p.global() != null && p.global().isFinite()) d = p.global().distanceTo(ballGlobal);
            else if (p.relative() != null && p.relative().isFinite() && self == null) d = p.relative().distanceTo(ballRel);
            else continue;
            best = Math.min(best, d);
        }
        return best;
    }
}

package phalanx.agent.action;

import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.comm.perception.PlayMode;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * 4.6.2 On Ball, the state machine of Figure 4.14: Walk To Ball, Find Opponent's Goal, align with
 * the goal (the tolerance grows with the distance to the goal: far away the ball only needs to
 * leave our half), Prepare For Kick, kick (the strong kick far from the goal). Whenever the ball is
 * lost or taken away it starts again from Walk To Ball. Ours: in PlayOn, with the ball nearer the
 * opponent goal than {@code AgentConfig.Kick.dribbleWithin}, the aligned player dribbles toward the
 * goal (Dribble Ball To Direction) instead of preparing a kick; set pieces are always kicked, since
 * a dribble touches the ball twice (docs/protocol.md, "Set pieces"). Ours too: with a self pose and
 * {@code AgentConfig.Approach.enabled}, the way to the ball is {@link ApproachBall} (to the spot behind
 * the ball, facing the goal, with the omnidirectional walk), so the align orbit has little left to do.
 * Ours too (issue 18): at the ball in PlayOn with an opponent near it ({@code AgentConfig.Kick.pressureDistance}),
 * and facing within pressureMaxDeg of the opponent goal, it walks the ball on along its heading at once
 * instead of going round it and lining up a kick, which an opponent at the ball does not wait for; walking to such a
 * ball it goes through it from where it stands once within {@code pressureReach}, as long as that push does not go back
 * toward our half. Within {@code shootWithin} of the opponent goal it does not dribble, and walks the ball on only when
 * that push goes into the goal's mouth; else it lines up and shoots.
 */
public final class OnBall implements Action {
    public enum State { WALK_TO_BALL, FIND_GOAL, ALIGN, PREPARE, KICK, DRIBBLE }

    private final AgentConfig config;
    private final WalkToBall walk;
    private final ApproachBall approach;
    private final FindOpponentGoal find;
    private final Orbit orbit;
    private final PrepareForKick prepare;
    private final KickBall kick;
    private final DribbleBallToDirection dribble;
    private State state = State.WALK_TO_BALL;
    private int kicks;
    private boolean justKicked;

    public OnBall(AgentConfig config) {
        this.config = config;
        this.walk = new WalkToBall(config);
        this.approach = new ApproachBall(config);
        this.find = new FindOpponentGoal(config);
        this.orbit = new Orbit(config);
        this.prepare = new PrepareForKick(config);
        this.kick = new KickBall(config);
        this.dribble = new DribbleBallToDirection(config, 0);
    }

    public State state() { return state; }

    /** Kicks played to their end since this action was created. */
    public int kicks() { return kicks; }

    @Override
    public Decision decide(Situation s) {
        justKicked = false;
        Vector2 ball = Facts.ball(s, config);
        if (state != State.KICK && lost(ball)) state = State.WALK_TO_BALL;
        // A ball only heard from teammates (issue 19) is walked to, and looked at, until own sight takes over: no
        // kick or dribble on a report up to 1.5 s old.
        if (state != State.KICK && ball != null && Facts.ballHeard(s)) {
            state = State.WALK_TO_BALL;
            return walk.decide(s);
        }
        // Each state either acts or hands over to the next one in the same cycle; at most once round.
        for (int i = 0; i < State.values().length + 1; i++) {
            switch (state) {
                case WALK_TO_BALL -> {
                    if (contested(s, ball)) { state = State.DRIBBLE; continue; }
                    if (!walk.done(s)) {
                        boolean approaches = config.approach().enabled() && approach.usable(s) && !approach.done(s);
                        return approaches ? approach.decide(s) : walk.decide(s);
                    }
                    state = State.FIND_GOAL;
                }
                case FIND_GOAL -> {
                    if (!find.done(s)) return find.decide(s);
                    state = State.ALIGN;
                }
                case ALIGN -> {
                    double e = goalError(s);
                    if (Double.isNaN(e)) { state = State.FIND_GOAL; return find.decide(s); }
                    if (!Double.isNaN(pressedHeading(s))) { state = State.DRIBBLE; continue; }
                    if (Math.abs(e) > tolerance(s)) return orbit.step(s, ball, e);
                    state = dribbles(s) ? State.DRIBBLE : State.PREPARE;
                    if (state == State.PREPARE) prepare.choose(s, strong(s));
                }
                case DRIBBLE -> {
                    double toGoal = dribbles(s) ? goalDirection(s) : pressedHeading(s);
                    if (Double.isNaN(toGoal)) { state = State.ALIGN; continue; }
                    if (snaps(s, ball)) { state = State.PREPARE; prepare.choose(s, false, true); continue; }
                    dribble.direction(toGoal);
                    return dribble.decide(s);
                }
                case PREPARE -> {
                    if (prepare.quick() && !laneFree(s)) { state = State.DRIBBLE; continue; }
                    double e = goalError(s);
                    if (!Double.isNaN(e) && Math.abs(e) > 2 * tolerance(s)) { state = State.ALIGN; return orbit.step(s, ball, e); }
                    if (!prepare.done(s)) return prepare.decide(s);
                    state = State.KICK;
                    kick.start(s, prepare.strong(), prepare.leftFoot(), prepare.quick());
                }
                case KICK -> {
                    if (!kick.done(s)) {
                        Decision d = kick.decide(s);
                        if (!kick.done(s)) return d;
                    }
                    kicks++;
                    justKicked = true;
                    state = State.WALK_TO_BALL;
                    return walk.decide(s);
                }
            }
        }
        return walk.decide(s);
    }

    /** True in the cycle a kick has just ended. */
    @Override
    public boolean done(Situation s) { return justKicked; }

    /** Dribble rather than kick: PlayOn, and the ball within dribbleWithin of the opponent goal but not within shootWithin. */
    private boolean dribbles(Situation s) {
        double d = distanceToGoal(s);
        return s.playMode() == PlayMode.PLAY_ON && !Double.isNaN(d) && d < config.kick().dribbleWithin() && !shoots(d);
    }

    /** Near enough the opponent goal to shoot: no dribble, and under pressure a push only into the mouth. */
    private boolean shoots(double distanceToGoal) { return distanceToGoal < config.kick().shootWithin(); }

    /**
     * Pressed: PlayOn, an opponent within pressureDistance of the ball, and the push from here through the ball within
     * pressureMaxDeg of the direction to the opponent goal (within shootWithin: between its posts, Facts.goalMouthHalfAngle).
     * Then the direction to walk the ball on (field frame), else NaN.
     * The push is the line from the player to the ball (its heading once the ball is at its feet).
     */
    private double pressedHeading(Situation s) {
        AgentConfig.Kick k = config.kick();
        if (s.playMode() != PlayMode.PLAY_ON || k.pressureDistance() <= 0) return Double.NaN;
        Pose2 self = Facts.self(s, config);
        Vector2 ball = Facts.ballGlobal(s, config);
        double toGoal = goalDirection(s);
        if (self == null || Double.isNaN(toGoal) || !Facts.opponentNear(s, config, ball, k.pressureDistance())) return Double.NaN;
        Vector2 push = ball.minus(self.position());
        double dir = push.norm() < PUSH_AT_FEET ? self.thetaDeg() : push.angleDeg();
        // Near the goal only a push into the mouth: lining up a kick there beside an opponent took 9-24 s (session 23).
        double within = shoots(distanceToGoal(s)) ? Facts.goalMouthHalfAngle(s, ball) : k.pressureMaxDeg();
        return Math.abs(Angles.difference(dir, toGoal)) <= within ? dir : Double.NaN;
    }

    /**
     * A quick shot: dribbling in PlayOn between shootWithin and snapWithin of the opponent goal with the heading on the
     * goal (the alignment tolerance) and the ball just ahead (within QUICK_REACH ahead, QUICK_SIDE aside): Prepare For
     * Kick puts it on the quick kick's spot, which is kicked without the stand before it (act.Body). The dribble keeps the
     * ball between the feet, 0.1-0.6 m ahead, where no kick's spot is (session 26), so it must be put there.
     */
    private boolean snaps(Situation s, Vector2 ball) {
        AgentConfig.Kick k = config.kick();
        double d = distanceToGoal(s);
        if (k.snapWithin() <= 0 || s.playMode() != PlayMode.PLAY_ON || ball == null || Double.isNaN(d) || d > k.snapWithin() || shoots(d))
            return false;
        double e = goalError(s);
        return !Double.isNaN(e) && Math.abs(e) <= tolerance(s) && ball.x() > 0 && ball.x() <= QUICK_REACH && Math.abs(ball.y()) <= QUICK_SIDE
                && laneFree(s);
    }

    /**
     * No opponent stands in the shot's first LANE_LENGTH beyond the ball, within LANE_HALF_WIDTH of the line from the ball
     * to the goal's aim point. Against UT Austin Villa 4 of the 5 quick kicks of session 26's game u4 went off with a
     * defender 0.1-0.2 m beyond the ball and 0-0.28 m aside, and moved the ball 0-0.2 m; the fifth, with the defender
     * behind, went 3.44 m.
     */
    private boolean laneFree(Situation s) {
        Vector2 ball = Facts.ballGlobal(s, config);
        double dir = goalDirection(s);
        if (ball == null || Double.isNaN(dir) || s.belief() == null) return false;
        Vector2 u = Vector2.polar(1, dir);
        for (var p : s.belief().opponents()) {
            if (!Facts.seen(p, s.belief().time(), config)) continue;
            Vector2 v = p.global().minus(ball);
            double along = v.dot(u), across = Math.abs(v.x() * u.y() - v.y() * u.x());
            if (along > -LANE_BEHIND && along < LANE_LENGTH && across < LANE_HALF_WIDTH) return false;
        }
        return true;
    }

    /** The shot's lane (m): an opponent this far beyond the ball (or this little behind it) and this near the line blocks it. */
    private static final double LANE_LENGTH = 0.8, LANE_BEHIND = 0.05, LANE_HALF_WIDTH = 0.35;

    /** A quick shot's ball: at most this far ahead and this far aside (m). */
    private static final double QUICK_REACH = 0.5, QUICK_SIDE = 0.15;

    /** Nearer than this the ball is at the feet and the push goes along the heading, m. */
    private static final double PUSH_AT_FEET = 0.25;

    /** Walking to the ball, pressed, with the ball within pressureReach: go through it from here (a contest). */
    private boolean contested(Situation s, Vector2 ball) {
        double reach = config.kick().pressureReach();
        return reach > 0 && ball != null && ball.norm() <= reach && !Double.isNaN(pressedHeading(s));
    }

    /** Field-frame direction from the ball to where it aims at the opponent goal, degrees; NaN without a ball or field. */
    private double goalDirection(Situation s) {
        Vector2 from = Facts.ballGlobal(s, config);
        return from == null || s.field() == null ? Double.NaN : Facts.goalAim(s, from).minus(from).angleDeg();
    }

    /**
     * No ball, or (once at the ball) the ball got away: start again. A dribble pushes the ball on with every step, so
     * there it is away only beyond dribbleRestartDistance or when no longer ahead (more than 45° off the heading).
     */
    private boolean lost(Vector2 ball) {
        if (ball == null) return true;
        if (state == State.DRIBBLE && ball.x() > 0 && Math.abs(ball.y()) <= ball.x())
            return ball.norm() > Math.max(config.kick().restartDistance(), config.kick().dribbleRestartDistance());
        return state != State.WALK_TO_BALL && ball.norm() > config.kick().restartDistance();
    }

    /** Heading error to the goal's aim point as seen from the ball (degrees, + left), NaN without a self pose. */
    double goalError(Situation s) {
        Vector2 from = Facts.ballGlobal(s, config);
        Pose2 self = Facts.self(s, config);
        if (from == null && self != null) from = self.position();
        return FindOpponentGoal.goalBearingFrom(s, config, from);
    }

    /**
     * Alignment tolerance: in our half proportional to the ball's distance to the goal, within bounds (4.6.2:
     * there "we only want to clear the ball from our own half"); in the opponent's half the minimum, since a
     * kick from there should go at the goal (on an empty field 25° from 10 m out sent the ball to the corner
     * flag; docs/matches.md), unless the goal's mouth is wider than that as seen from the ball.
     */
    double tolerance(Situation s) {
        AgentConfig.Kick k = config.kick();
        double d = distanceToGoal(s);
        if (Double.isNaN(d)) return k.alignMaxDeg();
        Vector2 ball = Facts.ballGlobal(s, config);
        // Near the goal the mouth is wide: any heading that puts the ball between the posts will do (session 23: 0.3 m
        // from the line, the player went round the ball 10 s to be within 10 degrees of the middle, beside the keeper).
        if (ball != null && ball.x() > 0) return Math.max(k.alignMinDeg(), Facts.goalMouthHalfAngle(s, ball) - MOUTH_SPARE_DEG);
        return Facts.clamp(k.alignDegPerMetre() * d, k.alignMinDeg(), k.alignMaxDeg());
    }

    /** The kick's own error: the strong kick goes 4 degrees off its line on the bench (motions/README.md), and more from a walk, degrees. */
    private static final double MOUTH_SPARE_DEG = 10;

    private double distanceToGoal(Situation s) {
        Vector2 from = Facts.ballGlobal(s, config);
        Pose2 self = Facts.self(s, config);
        if (from == null && self != null) from = self.position();
        return from == null || s.field() == null ? Double.NaN : from.distanceTo(s.field().opponentGoal());
    }

    private boolean strong(Situation s) {
        double d = distanceToGoal(s);
        return Double.isNaN(d) || d > config.kick().strongBeyond();
    }
}

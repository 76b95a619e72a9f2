package phalanx.agent.goalkeeper;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.action.World;
import phalanx.agent.decide.Move;
import phalanx.localization.fall.FallState;

import static org.junit.jupiter.api.Assertions.*;

/** Thesis 5.13 with the keeper on its spot (-14.5, 0) facing the field, dive time 0.7 s, k = 1.06 /s. */
class GoalkeeperTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;

    /** A keeper already in GUARD on its spot. */
    private static Goalkeeper guarding() { return guarding(C); }

    private static Goalkeeper guarding(AgentConfig c) {
        Goalkeeper k = new Goalkeeper(c);
        k.decide(World.at(-14.5, 0, 0).ballAt(0, 0).situation());
        assertEquals(Goalkeeper.State.GUARD, k.state());
        return k;
    }

    private static World shot(double bx, double by, double vx, double vy) {
        return World.at(-14.5, 0, 0).ballAt(-14.5 + bx, by).ballVelocity(vx, vy);
    }

    @Test
    void divesToTheSideTheBallWillCross() {
        // 1 m out, 0.4 m left, (-3, 0.2) m/s: e^(-kt) = 1 - 1.06/3 = 0.647, t = 0.41 s <= 0.7 s; crosses at y = 0.467.
        Goalkeeper left = guarding();
        assertEquals(new Move.Dive(true), left.decide(shot(1, 0.4, -3, 0.2).situation()).move());
        assertEquals(Goalkeeper.State.DIVING, left.state());
        Goalkeeper right = guarding();
        assertEquals(new Move.Dive(false), right.decide(shot(1, -0.4, -3, -0.2).situation()).move());
    }

    @Test
    void noDiveForAWideSlowDistantOrCentralBall() {
        // Wide: crosses at y = 1.6 m, outside the post (1.05) plus margin (0.15).
        assertNoDive(shot(1, 1.4, -3, 0.6));
        // Too slow: reach 0.5 / 1.06 = 0.47 m, it stops before the line.
        assertNoDive(shot(1, 0.4, -0.5, 0));
        // Not yet: 3 m out at 6 m/s, t = -ln(1 - 1.06 * 3 / 6) / 1.06 = 0.71 s > 0.7 s.
        assertNoDive(shot(3, 0.5, -6, 0));
        // ... but 2.5 m out at 6 m/s it is t = -ln(1 - 1.06 * 2.5 / 6) / 1.06 = 0.55 s: dive.
        assertEquals(new Move.Dive(true), guarding().decide(shot(2.5, 0.5, -6, 0).situation()).move());
        // Straight at the body (|y| <= 0.14 m: the feet reach 0.095 m, the ball's radius is 0.042 m): the body blocks it.
        assertNoDive(shot(1, 0.05, -3, 0));
        assertNoDive(shot(1, 0.13, -3, 0));
        // Rolling away.
        assertNoDive(shot(1, 0.4, 3, 0));
        // Without a self pose the ball's velocity cannot be put in the body frame: no dive.
        World lost = World.lost().ballRel(1, 0.4).ballVelocity(-3, 0.2);
        assertNoDive(lost);
    }

    @Test
    void aBallPushedAlongByAnOpponentIsNoShot() {
        // 0.35 m out, 0.4 m left (0.53 m away), rolling in at 0.8 m/s: e^(-kt) = 1 - 1.06 * 0.35 / 0.8 = 0.536, t = 0.59 s.
        World alone = shot(0.35, 0.4, -0.8, 0);
        assertEquals(new Move.Dive(true), guarding().decide(alone.situation()).move(), "nobody near: a dive");
        // The same ball with an opponent 0.3 m behind it (within 0.6 m): walked into the keeper, not shot.
        assertNoDive(shot(0.35, 0.4, -0.8, 0).opponentAt(9, -14.5 + 0.65, 0.4));
        // Shot at 3 m/s with the kicker still next to it: a dive.
        World kicked = shot(1, 0.4, -3, 0).opponentAt(9, -14.5 + 1.3, 0.4);
        assertEquals(new Move.Dive(true), guarding().decide(kicked.situation()).move());
        // An opponent 1 m from the ball does not count.
        World far = shot(0.35, 0.4, -0.8, 0).opponentAt(9, -14.5 + 1.35, 0.4);
        assertEquals(new Move.Dive(true), guarding().decide(far.situation()).move());
        // A ball at the feet (0.2 m ahead, 0.3 m left: 0.36 m < 0.5 m) is never dived for, however fast.
        assertNoDive(shot(0.2, 0.3, -3, 0.2));
    }

    @Test
    void guardSideStepsOntoTheLineFromTheGoalsCentreToTheBall() {
        // Ball at (-11, -2.67), 4 m out (beyond Challenge's 3 m): the line from the goal's centre (-15, 0) crosses
        // x = -14.5 at y = -2.67 * 0.5 / 4 = -0.33, more than 0.15 m to the keeper's right: side-step right.
        Goalkeeper k = guarding();
        assertEquals(new Move.SideStep(false), k.decide(World.at(-14.5, 0, 0).ballAt(-11, -2.67).situation()).move());
        // At y = -0.25 it is 0.08 m off: still stepping (it stops within 0.05 m) ...
        assertEquals(new Move.SideStep(false), k.decide(World.at(-14.5, -0.25, 0).ballAt(-11, -2.67).situation()).move());
        // ... and at -0.30 it stands; 0.10 m off (under the 0.15 m to start) it stays standing.
        assertEquals(Move.STAND, k.decide(World.at(-14.5, -0.30, 0).ballAt(-11, -2.67).situation()).move());
        assertEquals(Move.STAND, k.decide(World.at(-14.5, -0.23, 0).ballAt(-11, -2.67).situation()).move());
        // A ball far out on the wing: at most 0.5 m from the middle; the ball on the goal line beside the post too.
        assertEquals(new Move.SideStep(true), guarding().decide(World.at(-14.5, 0, 0).ballAt(-14.8, 3).situation()).move());
        Goalkeeper g = guarding();
        assertEquals(Move.STAND, g.decide(World.at(-14.5, 0.45, 0).ballAt(-10, 8).situation()).move(), "0.5 m cap");
        // The thesis's keeper keeps the middle.
        Goalkeeper t = guarding(C.withKeeper(AgentConfig.Keeper.THESIS));
        assertEquals(Move.STAND, t.decide(World.at(-14.5, 0, 0).ballAt(-11, -2.67).situation()).move());
    }

    @Test
    void guardStepsBackToTheSpotsDepthWhenItHasDriftedOntoItsLine() {
        // Session 23: the keeper stood on its goal line, 0.5 m behind its spot (x = -14.5), for most of some halves (its
        // side steps drift back, and the spot is walked to again only 0.7 m off it); UT Austin Villa scored past it there.
        Goalkeeper k = guarding();
        assertEquals(Move.STAND, k.decide(World.at(-14.6, 0, 0).ballAt(-5, 0).situation()).move(), "0.1 m off: within 0.2 m");
        Move back = k.decide(World.at(-14.8, 0, 0).ballAt(-5, 0).situation()).move();
        assertEquals(Goalkeeper.State.GUARD, k.state());
        assertTrue(back instanceof Move.Omni o && o.forward() > 0 && Math.abs(o.left()) < 1e-9 && Math.abs(o.turn()) < 1e-9, back.toString());
        assertTrue(k.decide(World.at(-14.6, 0, 0).ballAt(-5, 0).situation()).move() instanceof Move.Omni, "on until within 0.07 m");
        assertEquals(Move.STAND, k.decide(World.at(-14.52, 0, 0).ballAt(-5, 0).situation()).move());
    }

    private static void assertNoDive(World w) {
        Goalkeeper k = guarding();
        Move m = k.decide(w.situation()).move();
        assertFalse(m instanceof Move.Dive, m.toString());
        assertNotEquals(Goalkeeper.State.DIVING, k.state());
    }

    @Test
    void theDivePlaysOnceThenTheKeeperLocalizesAgain() {
        Goalkeeper k = guarding();
        World w = shot(1, 0.4, -3, 0.2).time(20);
        assertEquals(new Move.Dive(true), k.decide(w.situation()).move());
        w.motion("dive_left", null, 0).time(20.04);
        assertEquals(Move.STAND, k.decide(w.situation()).move(), "playing: not requested again");
        assertTrue(k.diving());
        w.motion(null, "dive_left", 1).time(21.5).fall(FallState.FALLEN_BACK);
        k.decide(w.situation());
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
    }

    @Test
    void localizeWalksToTheSpotThenGuards() {
        Goalkeeper k = new Goalkeeper(C);
        Move m = k.decide(World.at(-11, 0, 0).ballAt(0, 0).situation()).move();
        assertTrue(m instanceof Move.Turn, "spot 3.5 m behind: turn first, " + m);
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
        assertEquals(Move.STAND, k.decide(World.at(-14.45, 0.1, 3).ballAt(0, 0).situation()).move());
        assertEquals(Goalkeeper.State.GUARD, k.state());
        // Pushed 1 m off the spot with no shot coming: back to LOCALIZE.
        k.decide(World.at(-13.5, 0, 0).ballAt(0, 0).situation());
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
    }

    /** Back to the spot from the field's side within 3 m: backwards, facing the field, the head on the ball. */
    @Test
    void localizeWalksBackwardsToTheSpotFacingTheField() {
        // 2.5 m straight out from the spot, facing the field: straight back at full backward speed, no turn.
        Goalkeeper k = new Goalkeeper(C);
        Move m = k.decide(World.at(-12, 0, 0).ballAt(-5, 0).situation()).move();
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
        assertEquals(new Move.Omni(-1, 0, 0), m);
        // Out at 60 degrees from the spot (session 25's FCP game, 354 s: (-13.52, 1.71)): it faces straight away from
        // the spot (60 deg, so the field) and walks backwards; facing 30 deg it turns left toward 60.
        Move.Omni o = (Move.Omni) new Goalkeeper(C).decide(World.at(-13.5, 1.732, 60).ballAt(-9, 3).situation()).move();
        assertEquals(-1, o.forward(), 1e-3);
        assertEquals(0, o.left(), 0.01);
        assertEquals(0, o.turn(), 0.01);
        o = (Move.Omni) new Goalkeeper(C).decide(World.at(-13.5, 1.732, 30).ballAt(-9, 3).situation()).move();
        assertTrue(o.turn() > 0.5, "turning left toward 60 deg: " + o);
        // Beside the spot (on its line) or past it toward the goal line: the usual walk, facing where it goes.
        assertInstanceOf(Move.Turn.class, new Goalkeeper(C).decide(World.at(-14.5, 2, 0).ballAt(-5, 0).situation()).move());
        // Farther than 3 m: the usual walk (turn round first).
        assertInstanceOf(Move.Turn.class, new Goalkeeper(C).decide(World.at(-11.2, 0, 0).ballAt(-5, 0).situation()).move());
        // At the spot: turns to face the field, then guards.
        Goalkeeper g = new Goalkeeper(C);
        g.decide(World.at(-14.45, 0.1, 3).ballAt(-5, 0).situation());
        assertEquals(Goalkeeper.State.GUARD, g.state());
    }

    @Test
    void liberoClearsABallLyingInTheGoalAreaWhenNobodyIsNearIt() {
        AgentConfig thesis = C.withKeeper(AgentConfig.Keeper.THESIS);
        Goalkeeper k = guarding(thesis);
        k.decide(World.at(-14.5, 0, 0).ballAt(-13.5, 0.5).situation());
        assertEquals(Goalkeeper.State.LIBERO, k.state());
        assertTrue(k.hasBall());
        // Cleared: the ball left the goal area (1.8 m deep) by more than 0.5 m.
        k.decide(World.at(-13.8, 0.3, 0).ballAt(-11, 0).situation());
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
        assertFalse(k.hasBall());
        // A ball rolling through the goal area at 2 m/s is not Libero's.
        Goalkeeper r = guarding(thesis);
        r.decide(World.at(-14.5, 0, 0).ballAt(-13.5, 1.5).ballVelocity(0, 2).situation());
        assertEquals(Goalkeeper.State.GUARD, r.state());
        // An opponent next to the ball: the keeper stays in its goal.
        Goalkeeper g = guarding(thesis);
        g.decide(World.at(-14.5, 0, 0).ballAt(-13.5, 0.5).opponentAt(9, -13.2, 0.8).situation());
        assertEquals(Goalkeeper.State.GUARD, g.state());
        // Our default while kicks end on the ground: no Libero (it comes out to push the ball away instead, below).
        Goalkeeper d = guarding();
        d.decide(World.at(-14.5, 0, 0).ballAt(-13.5, 0.5).situation());
        assertNotEquals(Goalkeeper.State.LIBERO, d.state());
        assertFalse(d.hasBall());
    }

    @Test
    void challengeWalksThroughABallNearTheGoalFromTheGoalsSideAndGoesBackOnceItIsOut() {
        // Ball at (-13.5, 0.2): 1.5 m from the goal line, inside the 3 m box. The point 0.3 m past it on the line
        // from (-15, 0), (-13.20, 0.24), is nearly straight ahead of the keeper at (-14.5, 0.1) facing +x (6 deg): walk.
        Goalkeeper k = guarding();
        Move m = k.decide(World.at(-14.5, 0.1, 0).ballAt(-13.5, 0.2).situation()).move();
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        assertTrue(m instanceof Move.Walk, m.toString());
        assertFalse(k.hasBall(), "the field players keep playing the ball");
        // Still inside the box plus its 0.7 m margin (3.5 m out): still challenging.
        k.decide(World.at(-13.8, 0.3, 0).ballAt(-11.5, 0.5).situation());
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        // Pushed out beyond 3.7 m: back to the spot.
        k.decide(World.at(-13.8, 0.3, 0).ballAt(-11, 0).situation());
        assertEquals(Goalkeeper.State.LOCALIZE, k.state());
        // A ball 4 m out, or wide of the box (y = 3 m), is left to the field players.
        Goalkeeper g = guarding();
        g.decide(World.at(-14.5, 0, 0).ballAt(-11, 0).situation());
        assertEquals(Goalkeeper.State.GUARD, g.state());
        g.decide(World.at(-14.5, 0, 0).ballAt(-13, 3).situation());
        assertEquals(Goalkeeper.State.GUARD, g.state());
        // The thesis's keeper does not come out (it goes Libero for a still ball in the goal area instead).
        Goalkeeper t = guarding(C.withKeeper(AgentConfig.Keeper.THESIS));
        t.decide(World.at(-14.5, 0, 0).ballAt(-12.8, 0.5).situation());
        assertEquals(Goalkeeper.State.GUARD, t.state());
        // A shot is still dived for while challenging.
        Goalkeeper d = guarding();
        d.decide(World.at(-14.5, 0, 0).ballAt(-13.5, 0.5).situation());
        assertEquals(Goalkeeper.State.CHALLENGE, d.state());
        assertEquals(new Move.Dive(true), d.decide(shot(1, 0.4, -3, 0.2).situation()).move());
    }

    @Test
    void challengeWithoutASelfPoseTurnsToLocalizeWithTheHeadPanningNotTrackingTheBall() {
        Goalkeeper k = guarding();
        k.decide(World.at(-14.5, 0.1, 0).ballAt(-13.5, 0.2).situation());
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        World lost = World.at(-14.5, 0.1, 0).ballAt(-13.5, 0.2);
        lost.selfAge = 60;    // the self pose long stale, the ball still believed where it lies
        phalanx.agent.decide.Decision d = k.decide(lost.situation());
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        phalanx.agent.decide.Decision localize = new phalanx.agent.action.TurnToLocalize(C).decide(lost.situation());
        assertEquals(localize.move(), d.move(), "turns to localize");
        assertEquals(localize.head(), d.head(), "the head pans as Turn To Localize's does");
        phalanx.agent.decide.Decision seen = k.decide(World.at(-14.5, 0.1, 0).ballAt(-13.5, 0.2).situation());
        assertNotEquals(localize.head(), seen.head(), "with a pose again the head tracks the ball");
    }

    @Test
    void challengeStopsAtThePenaltyAreasEdge() {
        // Ball at (-12.4, 0), 2.6 m out: in the Challenge box but outside the 1.8 m penalty area, where the server's
        // charging rule no longer spares a goalie. The keeper walks out to the area's edge (x = -13.35) and stops there.
        Goalkeeper k = guarding();
        Move out = k.decide(World.at(-14.5, 0, 0).ballAt(-12.4, 0).situation()).move();
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        assertTrue(out instanceof Move.Walk, out.toString());
        Move atEdge = k.decide(World.at(-13.35, 0, 0).ballAt(-12.4, 0).situation()).move();
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        assertFalse(atEdge instanceof Move.Walk || atEdge instanceof Move.Omni, "walked on past the area: " + atEdge);
    }

    @Test
    void challengeLeavesTheAreaSlowlyForABallLyingJustOutsideIt() {
        // Session 20's g3: the ball lay still at (-13.06, 0.05), 0.14 m outside the area's edge (x = -13.2), and the
        // keeper stood at (-13.55, -0.12), stopped by the edge, until UT Austin Villa shot past it. Now it goes on
        // through the ball, under the charging speed once within 0.4 m of the edge.
        Goalkeeper k = guarding();
        k.decide(World.at(-14.5, 0, 0).ballAt(-13.06, 0.05).situation());
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        Move fast = k.decide(World.at(-14.3, 0, 0).ballAt(-13.06, 0.05).situation()).move();
        assertEquals(new Move.Walk(0, false).getClass(), fast.getClass(), fast.toString());
        assertFalse(((Move.Walk) fast).slow(), "deep in the area it walks at full speed: " + fast);
        Move atEdge = k.decide(World.at(-13.55, -0.12, 10).ballAt(-13.06, 0.05).situation()).move();
        assertTrue(atEdge instanceof Move.Walk w && w.slow() || atEdge instanceof Move.Omni o && o.forward() <= C.charging().speedShare(),
                "walks on slowly: " + atEdge);
        Move pastEdge = k.decide(World.at(-13.35, 0.05, 0).ballAt(-13.06, 0.05).situation()).move();
        assertTrue(pastEdge instanceof Move.Walk w && w.slow() || pastEdge instanceof Move.Omni o && o.forward() > 0 && o.forward() <= C.charging().speedShare(),
                "walks on out of the area, slowly: " + pastEdge);
        // The keeper that stays inside (challengeOutside 0) stops at the edge as before.
        Goalkeeper in = guarding(C.withKeeper(withOutside(C.keeper(), 0)));
        in.decide(World.at(-14.5, 0, 0).ballAt(-13.06, 0.05).situation());
        Move stays = in.decide(World.at(-13.35, 0.05, 0).ballAt(-13.06, 0.05).situation()).move();
        assertFalse(stays instanceof Move.Walk || stays instanceof Move.Omni, "walked out of the area: " + stays);
    }

    @Test
    void challengeGoesRoundABallBehindTheKeeperBeforeWalkingThroughIt() {
        // Session 21's g1, 422-427 s: the ball lay at (-14.95, 0.39) on our goal line, the keeper at (-14.5, 0.2) in front
        // of it and 0.47 m to the side of the push line from the goal's centre through the ball, u = (0.13, 0.99): walking
        // to the point past the ball it went by it. Now it first steps to the goal's side of the ball, on the push line.
        Goalkeeper k = guarding();
        k.decide(World.at(-14.5, 0.2, 90).ballAt(-14.95, 0.39).situation());
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        phalanx.model.field.Vector2 behind = k.challengeTarget();
        assertEquals(-14.99, behind.x(), 0.02, "behind the ball: " + behind);
        assertEquals(0.09, behind.y(), 0.02, "behind the ball: " + behind);
        // There, it walks through the ball along u, pushing it toward the post rather than over the line.
        k.decide(World.at(-14.99, 0.1, 83).ballAt(-14.95, 0.39).situation());
        assertTrue(k.challengeTarget().y() > 0.39 + 0.2, "through the ball: " + k.challengeTarget());
        // A keeper beyond the ball along the push (it got past it) first goes to its flank, on its own side.
        Goalkeeper b = guarding();
        b.decide(World.at(-14.6, 0.9, -90).ballAt(-14.95, 0.39).situation());
        phalanx.model.field.Vector2 flank = b.challengeTarget();
        assertTrue(flank.x() > -14.95 + 0.25 && flank.y() < 0.39, "the flank on the field side, not past the ball: " + flank);
        // A ball in front of the keeper is walked through at once, as before.
        Goalkeeper f = guarding();
        f.decide(World.at(-14.5, 0.1, 0).ballAt(-13.5, 0.2).situation());
        assertTrue(f.challengeTarget().x() > -13.5, "straight through the ball: " + f.challengeTarget());
    }

    @Test
    void challengeDoesNotStopShortOfItsPointBehindTheBall() {
        // Session 22's g8, 392-405 s: the ball at (-12.83, 0.62), the keeper 0.2-0.4 m from it on the goal's side but
        // off the push line (outside the cone it walks through from), facing along the line (16 deg). At (-13.055, 0.317)
        // it is 0.23 m from the point 0.3 m behind the ball: inside Walk To Coordinate's 0.25 m (0.5 m once there),
        // so it stood, for 9 s, until UT Austin Villa shot past it.
        Goalkeeper k = guarding();
        Move m = k.decide(World.at(-13.055, 0.317, 16).ballAt(-12.83, 0.62).situation()).move();
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        assertEquals(-13.118, k.challengeTarget().x(), 0.01);
        assertEquals(0.537, k.challengeTarget().y(), 0.01);
        // It steps there (to its left, facing the push): the point lies 0.22 m to the left of its heading, 0.05 m back.
        assertTrue(m instanceof Move.Omni o && o.left() > 0.2 && Math.abs(o.turn()) < 0.1, "steps on to the point behind the ball: " + m);
        // There, it walks through the ball.
        Move through = k.decide(World.at(-13.11, 0.53, 16).ballAt(-12.83, 0.62).situation()).move();
        assertTrue(k.challengeTarget().x() > -12.83, "past the ball: " + k.challengeTarget());
        assertTrue(through instanceof Move.Omni o && o.forward() > 0, through.toString());
    }

    @Test
    void challengeStepsBackToItsPointAtTheAreasEdgeWithoutTurningRound() {
        // Session 23's g3, 516-531 s: the ball over 1 m outside the area, here at (-12.1, 1.04), the Challenge's point
        // clamped to the area's edge (x = -13.35). A keeper 0.1 m beyond it steps back, still facing the field (it turned
        // round to walk back a few cm when the walk's tolerance was tightened instead, and fell).
        Goalkeeper k = guarding();
        Move m = k.decide(World.at(-13.25, 1.14, 20).ballAt(-12.1, 1.04).situation()).move();
        assertEquals(Goalkeeper.State.CHALLENGE, k.state());
        assertEquals(-13.35, k.challengeTarget().x(), 1e-9);
        assertTrue(m instanceof Move.Omni o && o.forward() < 0 && Math.abs(o.turn()) < 0.1, m.toString());
    }

    private static AgentConfig.Keeper withOutside(AgentConfig.Keeper k, double outside) {
        return new AgentConfig.Keeper(k.spotOffset(), k.diveSeconds(), k.postMargin(), k.bodyBlock(), k.ballDecay(), k.minApproachSpeed(),
                k.relocalizeDistance(), k.liberoClearance(), k.liberoExitMargin(), k.liberoMaxSpeed(), k.shotSpeed(), k.dribbleDistance(),
                k.minDiveDistance(), k.maxShift(), k.shiftTolerance(), k.libero(), k.challengeDepth(), k.challengeWidth(), k.challengeExit(),
                k.challengePush(), outside);
    }

    @Test
    void behaviourStandsUpWhenDownButNeverInterruptsADive() {
        GoalkeeperBehaviour b = new GoalkeeperBehaviour(C);
        b.decide(World.at(-14.5, 0, 0).ballAt(0, 0).situation());
        assertEquals(Goalkeeper.State.GUARD, b.state());
        World w = shot(1, 0.4, -3, 0.2).time(30);
        assertEquals(new Move.Dive(true), b.decide(w.situation()).move());
        w.motion("dive_left", null, 0).fall(FallState.FALLEN_BACK).time(30.5);
        assertEquals(Move.STAND, b.decide(w.situation()).move(), "lying on purpose: no stand-up yet");
        w.motion(null, "dive_left", 1).time(31.5);
        b.decide(w.situation());
        assertEquals(new Move.StandUp(false), b.decide(w.time(31.52).situation()).move());
    }
}

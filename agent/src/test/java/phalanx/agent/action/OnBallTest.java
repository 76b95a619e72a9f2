package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;

import static org.junit.jupiter.api.Assertions.*;

/** Figure 4.14 driven by a scripted ball: walk, find the goal, align, prepare, kick, start again. */
class OnBallTest {
    /** The thesis's On Ball (Walk To Ball, then the align orbit); ApproachBallTest has ours. */
    private static final AgentConfig C = AgentConfig.DEFAULT.withApproach(AgentConfig.Approach.THESIS);

    @Test
    void goesThroughItsStatesInOrder() {
        OnBall a = new OnBall(C);
        // 1. Ball 2 m ahead (in front of the right foot): walk.
        assertEquals(new Move.Walk(0, false), a.decide(World.at(0, 0, 0).ballRel(2, -0.055).time(10).situation()).move());
        assertEquals(OnBall.State.WALK_TO_BALL, a.state());

        // 2. At the ball, but the self belief is 2 s old: find the goal (stand, scan).
        World stale = World.at(0, 0, 90).ballRel(0.25, -0.055).time(12);
        stale.selfAge = 2;
        assertEquals(Move.STAND, a.decide(stale.situation()).move());
        assertEquals(OnBall.State.FIND_GOAL, a.state());

        // 3. Localized facing +y: the goal lies 91° to the right; go round the ball (step left).
        assertEquals(new Move.SideStep(true), a.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).time(12.5).situation()).move());
        assertEquals(OnBall.State.ALIGN, a.state());
        //    The side step left the ball 20° to the right: turn back to it before the next step.
        Move back = a.decide(World.at(0, 0, 90).ballRel(0.25, -0.09).time(13).situation()).move();
        assertTrue(back instanceof Move.Turn t && !t.left(), back.toString());

        // 4. Facing the goal, ball 0.25 m ahead: aligned, so prepare (slow forward step).
        assertEquals(new Move.Walk(0, true), a.decide(World.at(0, 0, 0).ballRel(0.25, -0.055).time(14).situation()).move());
        assertEquals(OnBall.State.PREPARE, a.state());

        // 5. Ball at the right foot, 15 m from the goal: the strong kick, requested until it plays.
        World kick = World.at(0, 0, 0).ballRel(0.17, -0.055).time(15);
        assertEquals(new Move.Kick(true, false), a.decide(kick.situation()).move());
        assertEquals(OnBall.State.KICK, a.state());
        kick.motion("strong_kick", null, 0).time(15.04);
        assertEquals(Move.STAND, a.decide(kick.situation()).move(), "playing: not requested again");
        assertFalse(a.done(kick.situation()));

        // 6. The kick ended, the ball is gone: one kick, and back to walking to the ball.
        World after = World.at(0, 0, 0).ballRel(4, 0).motion(null, "strong_kick", 1).time(16.5);
        assertTrue(a.decide(after.situation()).move() instanceof Move.Walk);
        assertEquals(1, a.kicks());
        assertTrue(a.done(after.situation()));
        assertEquals(OnBall.State.WALK_TO_BALL, a.state());
    }

    /** A ball only heard from teammates (issue 19) is walked to and looked at, never kicked or dribbled blind. */
    @Test
    void aHeardBallIsWalkedToAndNotKicked() {
        OnBall a = new OnBall(C);
        // Facing the goal, the ball reported 0.25 m ahead: seen, this would be PREPARE (goesThroughItsStatesInOrder, 4.).
        World w = World.at(0, 0, 0).ballRel(0.25, -0.055).heard(0.4).time(14);
        var d = a.decide(w.situation());
        assertEquals(OnBall.State.WALK_TO_BALL, a.state());
        assertEquals(Move.STAND, d.move(), "at the reported ball: stand and look");
        assertTrue(d.head().pitchDeg() < -30, "the head looks down at the reported spot: " + d.head());
        // Reported 3 m ahead: walked to.
        assertEquals(new Move.Walk(0, false), new OnBall(C).decide(World.at(0, 0, 0).ballRel(3, -0.055).heard(0.4).time(14).situation()).move());
        // Seen there: PREPARE as usual.
        OnBall seen = new OnBall(C);
        seen.decide(World.at(0, 0, 0).ballRel(0.25, -0.055).time(14).situation());
        assertEquals(OnBall.State.PREPARE, seen.state());
    }

    @Test
    void dribblesTowardTheGoalInsteadOfKickingWithinDribbleWithin() {
        AgentConfig dribbling = C.withKick(C.kick().withDribbleWithin(20));
        // At (0, 0) facing the goal (15 m away), ball 0.25 m ahead: aligned, so dribble: walk on, leaning toward
        // the goal's aim seen from the ball (the posts' bisector meets the line at y = -0.0002: 0.2129°, / 7°) and the
        // ball's side (-0.055 / 0.1).
        OnBall a = new OnBall(dribbling);
        Move m = a.decide(World.at(0, 0, 0).ballRel(0.25, -0.055).situation()).move();
        assertEquals(OnBall.State.DRIBBLE, a.state());
        assertTrue(m instanceof Move.Walk w && !w.slow() && Math.abs(w.lean() - (0.2129 / 7 - 0.55)) < 1e-4, m.toString());
        // Standing at (0, 3) facing +x: the goal (15, 0) lies at -11.3° from the ball, more than twice 7°: go round it.
        OnBall b = new OnBall(dribbling.withKick(dribbling.kick()));
        b.decide(World.at(0, 3, -5).ballRel(0.25, 0).situation());
        assertEquals(OnBall.State.DRIBBLE, b.state());
        Move round = b.decide(World.at(0, 3, 5).ballRel(0.25, 0).situation()).move();
        assertEquals(new Move.SideStep(true), round, "heading 5°, wanted -11.3°: step left to turn right round the ball");
        // 20 m from the goal (beyond dribbleWithin): prepare a kick as before.
        OnBall far = new OnBall(dribbling);
        far.decide(World.at(-6, 0, 0).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.PREPARE, far.state());
        // A set piece (our kick-off) is kicked, never dribbled (the taker may touch the ball once).
        OnBall kickOff = new OnBall(dribbling);
        World w = World.at(0, 0, 0).ballRel(0.25, -0.055);
        w.mode = phalanx.comm.perception.PlayMode.KICK_OFF_LEFT;
        kickOff.decide(w.situation());
        assertEquals(OnBall.State.PREPARE, kickOff.state());
        // The default (the thesis) always kicks.
        OnBall thesis = new OnBall(C);
        thesis.decide(World.at(0, 0, 0).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.PREPARE, thesis.state());
    }

    @Test
    void withAnOpponentAtTheBallItWalksTheBallOnInsteadOfLiningUpAKick() {
        // At (8, 0), 7 m from the goal, facing 20 deg left of it, the ball 0.2 m ahead: not aligned (10 deg in the
        // opponent's half), so on its own it goes round the ball (the align orbit) ...
        OnBall a = new OnBall(C);
        Move round = a.decide(World.at(8, 0, 20).ballRel(0.2, 0).situation()).move();
        assertEquals(OnBall.State.ALIGN, a.state());
        assertFalse(round instanceof Move.Walk, round.toString());
        // ... but with an opponent 0.5 m from the ball it walks on at once along its heading.
        OnBall b = new OnBall(C);
        Move m = b.decide(World.at(8, 0, 20).ballRel(0.2, 0).opponentAt(5, 8.6, 0.4).situation()).move();
        assertEquals(OnBall.State.DRIBBLE, b.state());
        assertTrue(m instanceof Move.Walk w && !w.slow(), m.toString());
        // Facing away from the goal (120 deg off) it does not push the ball back toward its own half.
        OnBall c = new OnBall(C);
        c.decide(World.at(0, 0, 120).ballRel(0.2, 0).opponentAt(5, 0.2, 0.6).situation());
        assertNotEquals(OnBall.State.DRIBBLE, c.state());
        // Off (pressureDistance 0): it lines up as before.
        OnBall d = new OnBall(C.withKick(C.kick().withPressureDistance(0)));
        d.decide(World.at(8, 0, 20).ballRel(0.2, 0).opponentAt(5, 8.6, 0.4).situation());
        assertEquals(OnBall.State.ALIGN, d.state());
        // Within shootWithin (4 m) of the goal it does not dribble, and with an opponent at the ball it walks on only
        // into the mouth: facing 30° (the near post is 22° off from the ball), it lines up its shot.
        OnBall e = new OnBall(C.withKick(C.kick().withDribbleWithin(8)));
        e.decide(World.at(12.8, 0, 30).ballRel(0.2, 0).opponentAt(5, 13.4, 0.4).situation());
        assertEquals(OnBall.State.ALIGN, e.state());
        OnBall f = new OnBall(C.withKick(C.kick().withDribbleWithin(8)));
        f.decide(World.at(12.8, 0, 0).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.PREPARE, f.state(), "aligned 2 m out: kick, not dribble");
        OnBall g = new OnBall(C.withKick(C.kick().withDribbleWithin(8).withShootWithin(0).withSnapWithin(0)));
        g.decide(World.at(12.8, 0, 0).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.DRIBBLE, g.state(), "shootWithin and snapWithin 0: dribble on as before");
    }

    @Test
    void pressedNearTheGoalWithTheHeadingOnItItPreparesAndPlaysTheQuickKick() {
        // At (7, 0) facing the goal (8 m off), an opponent 0.55 m from the ball beside and behind it, the ball 0.3 m ahead
        // between the feet: it prepares for the quick kick (not the dribble), steps up to its spot, and kicks it with the right foot.
        OnBall a = new OnBall(C);
        Move m = a.decide(World.at(7, 0, 0).ballRel(0.3, -0.01).opponentAt(5, 7.1, 0.5).situation()).move();
        assertEquals(OnBall.State.PREPARE, a.state());
        assertTrue(m instanceof Move.SideStep || m instanceof Move.Walk, m.toString());
        Move k = a.decide(World.at(7, 0, 0).ballRel(0.165, -0.04).opponentAt(5, 7.1, 0.5).situation()).move();
        assertEquals(OnBall.State.KICK, a.state());
        assertEquals(new Move.Kick(false, false, true), k);
        // The heading 20 deg off the goal, the ball 0.8 m ahead, or 15 m from the goal: it dribbles.
        OnBall d = new OnBall(C);
        d.decide(World.at(7, 0, 20).ballRel(0.3, -0.01).opponentAt(5, 7.6, 0.4).situation());
        assertEquals(OnBall.State.DRIBBLE, d.state());
        OnBall far = new OnBall(C);
        far.decide(World.at(7, 0, 0).ballRel(0.8, 0).opponentAt(5, 8.1, 0.3).situation());
        assertNotEquals(OnBall.State.PREPARE, far.state());
        OnBall e = new OnBall(C);
        e.decide(World.at(0, 0, 0).ballRel(0.3, -0.01).opponentAt(5, 0.6, 0.3).situation());
        assertEquals(OnBall.State.DRIBBLE, e.state(), "15 m from the goal: beyond snapWithin");
        // Off (snapWithin 0): it dribbles as before.
        OnBall f = new OnBall(C.withKick(C.kick().withSnapWithin(0)));
        f.decide(World.at(7, 0, 0).ballRel(0.3, -0.01).opponentAt(5, 7.1, 0.5).situation());
        assertEquals(OnBall.State.DRIBBLE, f.state());
    }

    @Test
    void aDefenderInTheShotsLaneStopsTheQuickShot() {
        // The defender 0.3 m beyond the ball and 0.3 m aside (session 26's u4: 4 of 5 quick kicks into a defender's legs): dribble on.
        OnBall b = new OnBall(C);
        b.decide(World.at(7, 0, 0).ballRel(0.3, -0.01).opponentAt(5, 7.6, 0.3).situation());
        assertEquals(OnBall.State.DRIBBLE, b.state(), "the lane is blocked");
        // Preparing with the lane free, then the defender steps into it: back to the dribble, no kick.
        OnBall p = new OnBall(C);
        p.decide(World.at(7, 0, 0).ballRel(0.3, -0.01).opponentAt(5, 7.1, 0.5).situation());
        assertEquals(OnBall.State.PREPARE, p.state());
        Move m = p.decide(World.at(7, 0, 0).ballRel(0.165, -0.04).opponentAt(5, 7.4, 0.1).situation()).move();
        assertEquals(OnBall.State.DRIBBLE, p.state());
        assertFalse(m instanceof Move.Kick, m.toString());
        // A defender 1 m beyond the ball, or 0.5 m aside of the lane, leaves it free.
        for (double[] at : new double[][]{{8.4, 0}, {7.6, 0.5}}) {
            OnBall f = new OnBall(C);
            f.decide(World.at(7, 0, 0).ballRel(0.3, -0.01).opponentAt(5, at[0], at[1]).opponentAt(6, 7.1, 0.5).situation());
            assertEquals(OnBall.State.PREPARE, f.state(), "a defender at " + at[0] + ", " + at[1]);
        }
    }

    @Test
    void aDribbleFollowsTheBallItPushedOnAndStartsAgainOnlyWhenItIsFarOrNotAhead() {
        // Pressed at (8, 0) facing 20°: DRIBBLE. Its step pushes the ball 0.9 m straight on (session 21: 0.5-1.4 m).
        OnBall a = new OnBall(C);
        a.decide(World.at(8, 0, 20).ballRel(0.2, 0).opponentAt(5, 8.6, 0.4).situation());
        assertEquals(OnBall.State.DRIBBLE, a.state());
        Move on = a.decide(World.at(8.1, 0.05, 20).ballRel(0.9, 0.05).opponentAt(5, 8.6, 1.0).situation()).move();
        assertEquals(OnBall.State.DRIBBLE, a.state(), "the ball it pushed on is followed, not approached again");
        assertTrue(on instanceof Move.Walk || on instanceof Move.Omni, on.toString());
        // 1.7 m ahead (beyond 1.5 m) or 0.9 m to the side (not ahead): taken away, start again.
        a.decide(World.at(8.1, 0.05, 20).ballRel(1.7, 0.1).opponentAt(5, 8.6, 1.0).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, a.state());
        OnBall b = new OnBall(C);
        b.decide(World.at(8, 0, 20).ballRel(0.2, 0).opponentAt(5, 8.6, 0.4).situation());
        b.decide(World.at(8, 0, 20).ballRel(0.3, 0.9).opponentAt(5, 8.6, 0.4).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, b.state());
        // Off (dribbleRestartDistance 0): the old rule, restartDistance (0.5 m) wherever the ball is.
        OnBall c = new OnBall(C.withKick(C.kick().withDribbleRestartDistance(0)));
        c.decide(World.at(8, 0, 20).ballRel(0.2, 0).opponentAt(5, 8.6, 0.4).situation());
        c.decide(World.at(8.1, 0.05, 20).ballRel(0.9, 0.05).opponentAt(5, 8.6, 1.0).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, c.state());
    }

    @Test
    void walkingToAContestedBallItGoesThroughItFromWhereItStandsUnlessThatPushesItTowardOurGoal() {
        // Session 21's g1 at 284 s: our player at (-12.2, -0.6) facing +x, the ball still at (-12.07, -0.96), an
        // opponent 0.2 m beyond it lining it up. It side-stepped toward the spot behind the ball for 10 s.
        OnBall a = new OnBall(C);
        Move m = a.decide(World.at(-12.2, -0.6, 0).ballAt(-12.07, -0.96).opponentAt(4, -11.87, -0.93).situation()).move();
        assertEquals(OnBall.State.DRIBBLE, a.state(), "through the ball toward -y (70° off the goal's direction), now");
        assertFalse(m instanceof Move.SideStep || m instanceof Move.Omni, "not the approach's side steps: " + m);
        // From the far side the push would go toward our goal: approach as before.
        OnBall b = new OnBall(C);
        b.decide(World.at(-11.6, -0.9, 180).ballAt(-12.07, -0.96).opponentAt(4, -12.3, -0.5).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, b.state());
        // Nobody near the ball, or the ball beyond pressureReach (0.8 m): the approach as before.
        OnBall c = new OnBall(C);
        c.decide(World.at(-12.2, -0.6, 0).ballAt(-12.07, -0.96).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, c.state());
        OnBall d = new OnBall(C);
        d.decide(World.at(-12.2, 0.3, 0).ballAt(-12.07, -0.96).opponentAt(4, -11.87, -0.93).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, d.state());
        // Off (pressureReach 0): the approach as before.
        OnBall e = new OnBall(C.withKick(C.kick().withPressure(0, C.kick().pressureMaxDeg())));
        e.decide(World.at(-12.2, -0.6, 0).ballAt(-12.07, -0.96).opponentAt(4, -11.87, -0.93).situation());
        assertEquals(OnBall.State.WALK_TO_BALL, e.state());
    }

    @Test
    void nearTheGoalAContestedBallIsPushedThroughOnlyIntoTheMouth() {
        // Session 22's g7 at 336-344 s: the ball still 3 m from the goal, an opponent at it, ours lining up a kick for 9 s.
        // From (11.9, -1.4) the push through the ball at (12.2, -1.2) heads 33.7° off +x; from the ball the posts (brought
        // in to ±0.9) lie 6.1° and 36.9° off: inside. A push from (12.2, -1.6) straight across the field misses.
        OnBall a = new OnBall(C);
        a.decide(World.at(11.9, -1.4, 30).ballAt(12.2, -1.2).opponentAt(4, 12.5, -1.0).situation());
        assertEquals(OnBall.State.DRIBBLE, a.state(), "into the mouth, now");
        OnBall b = new OnBall(C);
        b.decide(World.at(12.2, -1.6, 90).ballAt(12.2, -1.2).opponentAt(4, 12.5, -1.0).situation());
        assertNotEquals(OnBall.State.DRIBBLE, b.state(), "90° off +x: past the far post, so line up");
        // The same push 6 m out (beyond shootWithin) only has to be within 90° of the goal.
        OnBall c = new OnBall(C);
        c.decide(World.at(9.0, -4.0, 90).ballAt(9.0, -3.6).opponentAt(4, 9.3, -3.4).situation());
        assertEquals(OnBall.State.DRIBBLE, c.state());
    }

    @Test
    void startsAgainWhenTheBallIsTakenAwayOrLost() {
        OnBall a = new OnBall(C);
        a.decide(World.at(0, 0, 90).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.ALIGN, a.state());
        a.decide(World.at(0, 0, 90).ballRel(1.5, 0.5).situation());            // an opponent took it
        assertEquals(OnBall.State.WALK_TO_BALL, a.state());

        OnBall b = new OnBall(C);
        b.decide(World.at(0, 0, 0).ballRel(0.25, -0.055).situation());
        assertEquals(OnBall.State.PREPARE, b.state());
        World gone = World.at(0, 0, 0).ballRel(0.25, -0.055);
        gone.ballAge = 10;                                                         // not seen for 10 s
        assertTrue(b.decide(gone.situation()).move() instanceof Move.Turn, "looks for it");
        assertEquals(OnBall.State.WALK_TO_BALL, b.state());
    }

    @Test
    void nearTheGoalItKicksNormallyAndAlignsMorePrecisely() {
        OnBall a = new OnBall(C);
        // In the opponent's half (10 m out): the 10° minimum; 25 m away: 45° cap; in our half 2.5°/m × 16.8 m = 42°.
        // 2 m from the goal the mouth (posts brought in to ±0.9 m) spans ±24.2° from the ball, so less the kick's 10°
        // spare: 14.2°; 0.3 m from the line ±71.6°: 61.6°.
        assertEquals(14.23, a.tolerance(World.at(12.8, 0, 0).ballRel(0.2, 0).situation()), 0.01);
        assertEquals(61.57, a.tolerance(World.at(14.5, 0, 0).ballRel(0.2, 0).situation()), 0.01);
        assertEquals(45, a.tolerance(World.at(-10.2, 0, 0).ballRel(0.2, 0).situation()), 1e-9);
        assertEquals(42, a.tolerance(World.at(-2, 0, 0).ballRel(0.2, 0).situation()), 1e-6);
        assertEquals(10, a.tolerance(World.at(4.8, 0, 0).ballRel(0.2, 0).situation()), 1e-6);
        // Facing 20° left of the goal 2 m away: not aligned near the goal, aligned far from it.
        // (the ball lies 18° to the right, so the orbit turns back to it first)
        Move m = a.decide(World.at(12.83, 0, 20).ballRel(0.17, -0.055).situation()).move();
        assertTrue(m instanceof Move.Turn t && !t.left(), m.toString());
        assertEquals(OnBall.State.ALIGN, a.state());
        OnBall far = new OnBall(C);
        assertEquals(new Move.Kick(true, false), far.decide(World.at(-10.2, 0, 20).ballRel(0.17, -0.055).situation()).move());
        OnBall near = new OnBall(C);
        assertEquals(new Move.Kick(false, false), near.decide(World.at(11, 0, 0).ballRel(0.17, -0.055).situation()).move());
    }

    @Test
    void aBallLeftOfTheBodyIsKickedWithTheLeftFoot() {
        OnBall a = new OnBall(C);
        // Facing the goal 4 m out, ball 0.25 m ahead and 5 cm left: aligned, prepare with the left foot (forward step).
        assertEquals(new Move.Walk(0, true), a.decide(World.at(10.8, 0, 0).ballRel(0.25, 0.05).situation()).move());
        assertEquals(OnBall.State.PREPARE, a.state());
        // At the left foot's spot: the normal kick (near the goal) with the left foot.
        assertEquals(new Move.Kick(false, true), a.decide(World.at(10.9, 0, 0).ballRel(0.17, 0.055).time(1).situation()).move());
    }

    @Test
    void typeFourStrongKicksAtItsOwnFilesSpot() {
        // 20 m from the goal both take the strong kick, each at its spot: type 4 plays motions/type4/strong_kick.xml,
        // tuned 0.185 m ahead and 0.035 m right; with the ball 3.5 cm farther right it first steps aside.
        assertEquals(new Move.Kick(true, false), new OnBall(AgentConfig.forRobotType(0)).decide(World.at(-10.2, 0, 20).ballRel(0.195, -0.039).situation()).move());
        assertEquals(new Move.Kick(true, false), new OnBall(AgentConfig.forRobotType(4)).decide(World.at(-10.2, 0, 20).ballRel(0.185, -0.035).situation()).move());
        assertNotEquals(new Move.Kick(true, false), new OnBall(AgentConfig.forRobotType(4)).decide(World.at(-10.2, 0, 20).ballRel(0.187, -0.07).situation()).move());
    }
}

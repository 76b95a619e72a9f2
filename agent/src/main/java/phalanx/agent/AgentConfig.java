package phalanx.agent;

import phalanx.model.robot.NaoModel;

/**
 * Every constant of the agent's actions (thesis 4.6) and goalkeeper (5.13), in one place. Defaults
 * are the thesis's values where it gives one (the section is named); the others are marked
 * "ours": chosen here, to be tuned in games (agent/README.md).
 *
 * @param head       head motion: Pan Head, Scan, Track Object
 * @param beliefs    when a belief counts as fresh, usable or lost
 * @param walk       walking and turning: Walk To Direction, Walk To Coordinate, Walk To Ball
 * @param kick       Prepare For Kick and On Ball
 * @param obstacles  Avoid Obstacles (Algorithm 2)
 * @param keeper     the goalkeeper (5.13)
 * @param fallback   the field player's own choice while the coordinator is quiet
 * @param approach   On Ball's way to the ball (ours)
 * @param kickOff    our kick-off: a tap and a partner (ours)
 * @param charging   walking slowly into opponents, so the referee does not call us for charging (the server's rule)
 * @param setPieces  keeping out of what the referee clears at the opponents' set pieces (the server's rule)
 */
public record AgentConfig(Head head, Beliefs beliefs, Walk walk, Kick kick, Obstacles obstacles,
                          Keeper keeper, Fallback fallback, Approach approach, KickOff kickOff, Charging charging,
                          SetPieces setPieces) {

    /**
     * @param panAmplitudeDeg  Pan Head / Scan yaw swing each side (ours: ±90° with the 120° field of
     *                         view covers ±150° around the body; the neck allows ±120°, 4.6.2)
     * @param panPeriodSeconds one full left-right-left sweep (ours; 180°/s keeps about 11° between
     *                         two vision frames, well inside the 120° view)
     * @param scanPitchDownDeg Scan tilts between 0 and this (negative = down; ours)
     * @param legs             leg geometry for the camera height (Walk to Ball's forward kinematics, 4.6.2)
     * @param leadSeconds      Track Moving Object aims this far ahead of a moving ball (ours: vision
     *                         every 3 cycles plus one cycle of latency)
     */
    public record Head(double panAmplitudeDeg, double panPeriodSeconds, double scanPitchDownDeg,
                       NaoModel legs, double leadSeconds) {
        public static final Head DEFAULT = new Head(90, 2.0, -35, NaoModel.TYPE_0, 0.08);
    }

    /**
     * @param ballFreshSeconds   the ball counts as "visible" when seen within this (ours: about 5 vision frames)
     * @param ballLostSeconds    beyond this the ball is lost: On Ball starts again (ours)
     * @param selfFreshSeconds   Turn To Localize: the self belief must be refreshed within this (ours)
     * @param selfConfidence     ... and at least this confident (ours: EKF σ ≈ 0.2 m)
     * @param selfUsableSeconds  walking to a coordinate trusts a self belief this old (ours; no odometry yet)
     * @param playerMemorySeconds a seen player counts (obstacle, closer teammate) this long (ours)
     */
    public record Beliefs(double ballFreshSeconds, double ballLostSeconds, double selfFreshSeconds,
                          double selfConfidence, double selfUsableSeconds, double playerMemorySeconds) {
        public static final Beliefs DEFAULT = new Beliefs(0.3, 3.0, 0.5, 0.5, 3.0, 1.0);
    }

    /**
     * @param leanBelowDeg        Walk To Direction leans below this heading error, turns above (4.6.2: 7°)
     * @param gainMin             Turn Gain range (4.5.5: 0.3 .. 1.0) ...
     * @param gainMax
     * @param turnMinDeg          ... which turns 7 .. 40° per turn motion (4.5.5, Figure 4.10)
     * @param turnMaxDeg
     * @param positionTolerance   Walk To Coordinate: (x, y) reached within this (ours)
     * @param thetaToleranceDeg   Walk To Coordinate: θ reached within this (ours)
     * @param slowdownDistance    Walk Slowdown (4.5.5) within this of a target (ours)
     * @param ballStopDistance    Walk To Ball stops this far from the ball (ours; Prepare For Kick does the rest)
     * @param ballTurnToleranceDeg Turn To Ball is done within this (ours)
     */
    public record Walk(double leanBelowDeg, double gainMin, double gainMax, double turnMinDeg, double turnMaxDeg,
                       double positionTolerance, double thetaToleranceDeg, double slowdownDistance,
                       double ballStopDistance, double ballTurnToleranceDeg) {
        public static final Walk DEFAULT = new Walk(7, 0.3, 1.0, 7, 40, 0.25, 10, 0.6, 0.28, 10);
    }

    /**
     * @param spotX             the ball's place for a right-foot kick, forward of the torso (motions/README:
     *                          kick.xml and the motion bench put it 0.17 m ahead ...)
     * @param spotY             ... and 0.055 m to the right (the left foot's kick_left.xml: mirrored)
     * @param strongSpotX       the same for strong_kick.xml (the spot its search tuned it for) ...
     * @param strongSpotY       ... and its side (right foot; mirrored for the left)
     * @param toleranceX        Prepare For Kick accepts the ball up to this much nearer than
     *                          spotX (ours; a nearer ball was kicked off the shin)
     * @param toleranceFarX     ... but steps forward until the ball is at most this much farther than spotX (ours:
     *                          stopping at the far edge, toleranceX, left the strong kick's ball 2.5 cm far in a game,
     *                          and from there the strong kick goes 8 m instead of 10; docs/matches.md session 7)
     * @param toleranceY        ... and this much to either side (ours)
     * @param restartDistance   On Ball starts again when the ball gets this far while preparing (ours: taken away)
     * @param alignDegPerMetre  On Ball's alignment tolerance grows with the distance to the goal (4.6.2
     *                          "inversely proportional" precision; the rate is ours) ...
     * @param alignMinDeg       ... between this ...
     * @param alignMaxDeg       ... and this (ours)
     * @param strongBeyond      the strong kick beyond this distance to the opponent goal (ours)
     * @param oneShotTimeout    a kick or dive that never shows as played ends after this (ours; a missing motion file)
     * @param dribbleWithin     in PlayOn, On Ball dribbles toward the goal instead of kicking while the ball is
     *                          nearer the opponent goal than this (ours; 0 = always kick, the thesis's Figure 4.14; the player's
     *                          --dribble-within sets 8 m by default, chosen in games: docs/matches.md session 10)
     * @param pressureDistance  in PlayOn, at the ball with an opponent this near it, On Ball does not go round the ball
     *                          to line up a kick but walks it on at once (ours, issue 18: at UT Austin Villa's goals our
     *                          nearest player stood 0.3-0.7 m from the ball, lining up, while theirs kicked); 0 = never ...
     * @param pressureMaxDeg    ... when the push (from it to the ball) is within this of the direction to the opponent goal
     *                          (otherwise it would go toward our own goal); 90: any push not back toward our half
     *                          (session 21: 60, the heading's, before the push went from where the player stands)
     * @param shootWithin       ... but nearer the opponent goal than this it lines up and kicks (the normal kick) instead
     *                          of dribbling on, with or without an opponent near (ours, issue 18: in g18b our dribble
     *                          reached 2.5 m from UTA's goal and their keeper cleared it 16 s later); 0 = dribble on.
     *                          With an opponent at the ball it still walks the ball on when that push goes between the
     *                          posts (session 23: lining up beside an opponent there took 9-24 s)
     * @param dribbleRestartDistance while dribbling, On Ball starts again only when the ball is this far, or not ahead
     *                          (ours, issue 18: each step of the dribble pushes the ball 0.5-1.4 m on, and with
     *                          restartDistance every push sent the player back to the approach and the alignment: 30 of
     *                          35 dribbles in session 21's games ended so, the ball straight ahead; docs/matches.md)
     * @param pressureReach     pressed, a player walking to the ball goes through it from where it stands once the ball
     *                          is this near, instead of going round it to the spot behind it (ours, issue 18: in session
     *                          21's games the ball lay still with players of both teams within 1 m of it for 190-200 s a
     *                          game, and UT Austin Villa moved it next in 36 of 58 such contests; our player side-steps
     *                          at 0.1 m/s, slower still beside an opponent); 0 = only once aligned, as before
     * @param snapWithin        the quick shot (OnBall): dribbling (pressed or near the goal) with the ball within this of the
     *                          opponent goal, but not within shootWithin, the heading on the goal, the ball just ahead and
     *                          the shot's lane free of opponents, the ball is put on the quick kick's spot and kicked without
     *                          the stand before a kick (ours, issue 18: against UT Austin Villa 100 s a game of pressed
     *                          dribbling 4-12 m from their goal and no shot on goal in 13 games; docs/matches.md, sessions
     *                          26-27); 0 = never
     */
    /**
     * strong_kick.xml's ball spot, the one its search tuned it for (motions/README.md; `scripts/phalanx bench kick-search params
     * motions/strong_kick.xml`): a ball 1-2 cm nearer is struck earlier in the swing (its precursor went 6.6 m from 0.17 m
     * ahead against 8.9 m from 0.187 m; motion/README.md "Kicks and dives").
     */
    private static final double STRONG_X = 0.195, STRONG_Y = -0.039;

    public record Kick(double spotX, double spotY, double strongSpotX, double strongSpotY, double toleranceX, double toleranceFarX, double toleranceY, double restartDistance,
                       double alignDegPerMetre, double alignMinDeg, double alignMaxDeg, double strongBeyond,
                       double oneShotTimeout, double dribbleWithin, double pressureDistance, double pressureMaxDeg,
                       double shootWithin, double dribbleRestartDistance, double pressureReach, double snapWithin) {
        public static final Kick DEFAULT = new Kick(0.17, -0.055, STRONG_X, STRONG_Y, 0.03, 0.01, 0.025, 0.5, 2.5, 10, 45, 5.0, 4.0, 0,
                1.0, 90, 4.0, 1.5, 0.8, 12.0);

        /**
         * Type 4 (toes) plays its own strong kick, motions/type4/strong_kick.xml (the shared one falls in 4
         * of 10 kicks on that type), tuned for this spot (motions/README.md, `scripts/phalanx bench kick-search params`).
         */
        public static final Kick TYPE_4 = DEFAULT.withStrongSpot(0.185, -0.035);

        /**
         * quick_kick.xml's ball spot, right foot (motions/README.md: searched for it, 7.93 m median from it, 7.24 m with
         * the ball up to 2.5 cm off): ahead, and to the side (negative: right).
         */
        public static final double QUICK_X = 0.163, QUICK_Y = -0.041;

        /** The spot's distance ahead for the quick, strong or normal kick. */
        public double spotX(boolean strong, boolean quick) { return quick ? QUICK_X : spotX(strong); }

        /** The spot's sideways offset for the quick, strong or normal kick, left foot (the mirror) or right. */
        public double spotY(boolean strong, boolean quick, boolean leftFoot) { return quick ? (leftFoot ? -QUICK_Y : QUICK_Y) : spotY(strong, leftFoot); }

        /** The spot's distance ahead for the strong kick or the normal one. */
        public double spotX(boolean strong) { return strong ? strongSpotX : spotX; }

        /** The spot's sideways offset for the strong or normal kick, left foot (the mirror) or right. */
        public double spotY(boolean strong, boolean leftFoot) {
            double y = strong ? strongSpotY : spotY;
            return leftFoot ? -y : y;
        }

        /** The same with another strong-kick spot (a robot type with its own strong_kick.xml). */
        public Kick withStrongSpot(double x, double y) {
            return new Kick(spotX, spotY, x, y, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, pressureDistance, pressureMaxDeg, shootWithin, dribbleRestartDistance, pressureReach, snapWithin);
        }

        public Kick withDribbleWithin(double metres) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, metres, pressureDistance, pressureMaxDeg, shootWithin, dribbleRestartDistance, pressureReach, snapWithin);
        }

        public Kick withPressureDistance(double metres) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, metres, pressureMaxDeg, shootWithin, dribbleRestartDistance, pressureReach, snapWithin);
        }

        public Kick withDribbleRestartDistance(double metres) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, pressureDistance, pressureMaxDeg, shootWithin, metres, pressureReach, snapWithin);
        }

        /** The same with another reach and angle for walking through a contested ball (reach 0 = only once aligned). */
        public Kick withPressure(double reach, double maxDeg) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, pressureDistance, maxDeg, shootWithin, dribbleRestartDistance, reach, snapWithin);
        }

        public Kick withSnapWithin(double metres) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, pressureDistance, pressureMaxDeg, shootWithin, dribbleRestartDistance, pressureReach, metres);
        }

        public Kick withShootWithin(double metres) {
            return new Kick(spotX, spotY, strongSpotX, strongSpotY, toleranceX, toleranceFarX, toleranceY, restartDistance, alignDegPerMetre, alignMinDeg, alignMaxDeg,
                    strongBeyond, oneShotTimeout, dribbleWithin, pressureDistance, pressureMaxDeg, metres, dribbleRestartDistance, pressureReach, snapWithin);
        }
    }

    /**
     * On Ball's approach (ours, {@code action.ApproachBall}): with a self pose, the robot walks with the
     * omnidirectional walk to the spot behind the ball on the line from the opponent goal's centre through
     * it, turning on the way, instead of the thesis's Walk To Ball followed by the align orbit (Figure 4.14).
     *
     * @param enabled        false: the thesis's way
     * @param behind         the spot this far behind the ball's centre, inside Walk To Ball's stop distance (0.28 m)
     *                       so that On Ball goes on from there (Prepare For Kick steps the last centimetres;
     *                       at 0.25 m, in the first game, robots hovered around a spot 0.256 m from the ball)
     * @param sideClearance  a robot not yet behind the ball first goes to a point this far beside it, not through it
     * @param slowWithin     full speed beyond this distance to the spot, proportionally slower within it ...
     * @param minShare       ... but never below this share of it (the walk hardly moves on smaller requests)
     * @param faceWayBeyond  beyond this the robot faces where it walks (the walk is fastest forward); within
     *                       it, the goal. 0.3 m (was 1.0): within 1 m the robot slid sideways to the spot at the
     *                       walk's 0.1 m/s sideways limit; facing the spot it walks there at up to 0.88 m/s and turns
     *                       at the end. Bench approach: the first touch after 11.3 s instead of 18.5 s (median, 20
     *                       balls 1-3 m away), but shorter kicks (2.1 m against 8.7 m median) and more falls (9
     *                       against 4); in games 2:0 and 3:0 against Base (docs/matches.md, session 11)
     * @param turnFullDeg    a heading error this large or larger turns at the walk's full turn rate
     * @param arriveDistance done within this of the spot ...
     * @param arriveDeg      ... facing the goal within this
     */
    public record Approach(boolean enabled, double behind, double sideClearance, double slowWithin, double minShare,
                           double faceWayBeyond, double turnFullDeg, double arriveDistance, double arriveDeg) {
        public static final Approach DEFAULT = new Approach(true, 0.22, 0.45, 0.5, 0.3, 0.3, 30, 0.12, 12);
        /** The thesis's On Ball: Walk To Ball, then the align orbit. */
        public static final Approach THESIS = new Approach(false, 0.22, 0.45, 0.5, 0.3, 1.0, 30, 0.12, 12);
    }

    /**
     * @param range         obstacles within this are recorded (4.6.2: 2 m)
     * @param clearance     escape angles pass an obstacle's centre at this distance (ours: two robots'
     *                      half widths plus a margin)
     * @param angleWeight   way point cost = angleWeight · |angle overhead in rad| + distance overhead (m)
     *                      (4.6.2 names both overheads, not their weights; ours)
     */
    public record Obstacles(double range, double clearance, double angleWeight) {
        public static final Obstacles DEFAULT = new Obstacles(2.0, 0.45, 0.5);
    }

    /**
     * @param spotOffset        guard spot this far in front of the goal line (ours; coordination's GK spot too)
     * @param diveSeconds       time from requesting a dive until the body covers the side (5.13 "the time
     *                          it takes for our agent to fall"): dive_left/right.xml reach 90 % of their
     *                          0.70 m lateral reach 0.66-0.80 s (median of the medians 0.69 s) after the
     *                          request on types 0, 2 and 4
     *                          (`scripts/phalanx bench motion --only dive`, motion/README.md "Dives")
     * @param postMargin        Threshold_Left/Right = goal half width + this (5.13; the margin is ours)
     * @param bodyBlock         a ball crossing closer than this to the keeper's centre is left to the body (ours:
     *                          the feet reach 0.095 m out, the hip's 0.055 m (NaoModel) and half
     *                          the 0.08 m foot, plus the ball's 0.042 m radius; 0.08 m
     *                          before, and the keeper dived away from balls rolling at its feet in the 6.3 test)
     * @param ballDecay         rolling ball velocity decay rate, 1/s: v(t) = v0·e^(−k·t) (ours: 1.053
     *                          derived from SimSpark's ball.rsg drag, 1.062 measured by scripts/phalanx bench ball-decay)
     * @param minApproachSpeed  slower balls are not dived for (ours; tracker noise on a still ball)
     * @param relocalizeDistance Guard goes back to Localize when this far off its spot (ours)
     * @param liberoClearance   Libero only when no other player is this close to the ball (5.13 "no other
     *                          agents near"; the distance is ours)
     * @param liberoExitMargin  the ball is cleared when this far outside the goal area (ours)
     * @param liberoMaxSpeed    Libero only for a ball slower than this (ours: a shot rolling through
     *                          the goal area is Guard's business)
     * @param shotSpeed         with an opponent near the ball only a ball this fast is a shot worth a dive (ours:
     *                          in the 6.3 test FC Portugal's attackers walked the ball up to the keeper, it dived
     *                          for the push and lay there while the kick went in; docs/matches.md)
     * @param dribbleDistance   "near the ball" for shotSpeed (ours)
     * @param minDiveDistance   no dive for a ball nearer than this: it is at the feet, the body is already in its way
     *                          and a dive needs 0.7 s to cover anything (ours: in the 6.3 test the keeper dived for
     *                          balls 0.13-0.4 m in front of it and lay beside them while they were pushed in)
     * @param maxShift          Guard stands on the line from the goal's centre to the ball, at most this far
     *                          sideways from the spot (ours; the thesis's keeper keeps the middle)
     * @param shiftTolerance    Guard side-steps when this far off that line, and stops at a third of it (ours)
     * @param libero            whether Guard goes Libero at all (5.13: yes). Off by default while every kick
     *                          ends with the robot on the ground (motion/README.md): in the 6.3 test against
     *                          FC Portugal each Libero clearance left the keeper lying in front of an open goal
     *                          (docs/matches.md, scripts/phalanx keeper-test)
     * @param challengeDepth    Challenge: the keeper leaves its spot for a ball this near our goal line ... (ours,
     *                          issue 18: UT Austin Villa scored all its goals from 0.3-3.7 m, the keeper standing
     *                          on its line; docs/matches.md, session 14). 0: never
     * @param challengeWidth    ... and at most this far from the goal's middle line, m
     * @param challengeExit     it goes back to its spot once the ball is this much beyond that box, m
     * @param challengePush     it walks to the point this far past the ball on the line from the goal's centre,
     *                          so it meets the ball from the goal's side and pushes it away (no kick: ours end on
     *                          the ground, see libero), m
     * @param challengeOutside  a ball lying up to this far outside our penalty area is still challenged: the keeper
     *                          leaves the area for it, walking under the referee's charging speed there, since outside
     *                          the area the charging rule no longer spares it (ours, issue 18: in session 20 UT Austin
     *                          Villa scored twice from a ball lying 0.1-0.2 m outside the area while the keeper, stopped
     *                          at the edge, stood 0.5-0.7 m from it; docs/matches.md). 0: the keeper stays inside
     */
    public record Keeper(double spotOffset, double diveSeconds, double postMargin, double bodyBlock, double ballDecay,
                         double minApproachSpeed, double relocalizeDistance, double liberoClearance,
                         double liberoExitMargin, double liberoMaxSpeed, double shotSpeed, double dribbleDistance,
                         double minDiveDistance, double maxShift, double shiftTolerance, boolean libero,
                         double challengeDepth, double challengeWidth, double challengeExit, double challengePush,
                         double challengeOutside) {
        public static final Keeper DEFAULT = new Keeper(0.5, 0.7, 0.15, 0.14, 1.06, 0.2, 0.7, 1.0, 0.5, 1.0,
                1.0, 0.6, 0.5, 0.5, 0.15, false, 3.0, 2.5, 0.7, 0.3, 0.7);
        /** The thesis's keeper: Libero on, the middle of the goal, a dive for any approaching ball, no challenge. */
        public static final Keeper THESIS = new Keeper(0.5, 0.7, 0.15, 0.14, 1.06, 0.2, 0.7, 1.0, 0.5, 1.0,
                0.2, 0.6, 0.0, 0.0, 0.15, true, 0.0, 2.5, 0.7, 0.3, 0.0);
    }

    /**
     * @param onBallDistance  while the coordinator is quiet a player goes On Ball when the ball is this
     *                        near and no teammate is seen closer (ours; comm.team.round.FieldPlayerRounds's fallback)
     * @param hysteresis      a teammate must be this much closer to take the ball over (ours)
     * @param keepBallWithin  a player the coordinator took off On Ball while the ball was this near it keeps
     *                        On Ball until the ball is farther (ours, issue 18: the coordinator's reports are a round
     *                        old and coarse, and in games vs UT Austin Villa it took On Ball away from players
     *                        dribbling the ball 0.2-0.5 m ahead 14-20 times a game; docs/matches.md, session 15); 0 = never
     */
    public record Fallback(double onBallDistance, double hysteresis, double keepBallWithin) {
        public static final Fallback DEFAULT = new Fallback(5.0, 0.5, 0.5);
    }

    /**
     * Our kick-off (ours, issue 18): the taker's first touch turns KickOff into PlayOn, and any touch of
     * the taker 0.1 s or more later, before another robot's, is a foul and a free kick for the other side
     * (docs/protocol.md, "Set pieces"); On Ball's kick after its first nudge made every kick-off one. So
     * the taker only taps the ball with slow forward steps and then leaves it to a partner, who waits
     * beside the centre spot and plays it with On Ball once the mode is PlayOn.
     *
     * @param enabled         false: On Ball as in any other mode
     * @param taker           the taker's player number (10, the centre forward: its kick-off spot is the
     *                        nearest to the ball)
     * @param partner         the partner's player number (9)
     * @param partnerX        the partner's kick-off beam, own-team frame (the ball on the centre spot), m:
     *                        behind the ball and to the right of the taker's path, out of its way
     * @param partnerY
     * @param holdSeconds     after the tap the taker leaves the ball alone this long ...
     * @param releaseDistance ... or until the ball is this far from the centre spot (someone else moved it)
     */
    public record KickOff(boolean enabled, int taker, int partner, double partnerX, double partnerY,
                          double holdSeconds, double releaseDistance) {
        /** The tap (`--kick-off tap`). Not the default: in games 4 of its 14 kick-offs were fouls, the old kick's 0 of 4 (docs/matches.md, sessions 12-13). */
        public static final KickOff TAP = new KickOff(true, 10, 9, -0.55, -0.45, 6.0, 1.0);
        public static final KickOff OFF = new KickOff(false, 10, 9, -0.55, -0.45, 6.0, 1.0);
        public static final KickOff DEFAULT = OFF;
    }

    /**
     * The referee's charging foul (SoccerRuleAspect::AnalyseChargingFouls, naosoccersim.rb; docs/protocol.md "Charging
     * and crowding"): a robot that walks into an opponent at ChargingMinSpeed 0.4 m/s or more is taken off unless, within
     * ChargingMaxBallRulesDist 1 m of the ball, it heads for the ball and is the nearer of the two to it, or it touched
     * the ball within the last second. Not in the thesis (its server had no such rule); the numbers are ours.
     *
     * @param enabled        slow down at all
     * @param range          an opponent's torso within this of ours ... (the walk needs ~0.4 m to slow from full speed)
     * @param aheadDeg       ... and within this of the way we walk, is one we could run into
     * @param speedShare     walk at most this share of the walk's limits near him (0.4 × 0.88 m/s: under 0.4 m/s)
     * @param ballRulesDistance within this of the ball (either of us) the server asks who heads for it and is nearer ...
     * @param nearerMargin   ... so we keep our speed when heading for it and nearer than he is by this
     * @param onBallWithin   the ball this close: we are on it (dribbling touches it all the time: immune), keep going
     */
    public record Charging(boolean enabled, double range, double aheadDeg, double speedShare, double ballRulesDistance,
                           double nearerMargin, double onBallWithin) {
        public static final Charging DEFAULT = new Charging(true, 1.0, 60, 0.4, 1.0, 0.1, 0.3);
        public static final Charging OFF = new Charging(false, 1.0, 60, 0.4, 1.0, 0.1, 0.3);
    }

    /**
     * The referee's clearing at the opponents' kick-off and set pieces (SoccerRuleAspect::ClearPlayers, naosoccersim.rb:
     * FreeKickDistance 2 m, FreeKickMoveDist 2.5 m; docs/protocol.md "Their set pieces"). Not in the thesis; ours.
     *
     * @param enabled    keep out at all (TheirSetPiece)
     * @param keepOut    stay this far from the ball: the server moves a robot whose box meets the 2 m sphere, and the box
     *                   reaches ~0.2 m out from the torso, m
     * @param tolerance  a place this much inside keepOut still counts as out (so a player at the line does not dither), m
     * @param halfMargin at their kick-off stay this far on our side of the half-way line (the half is cleared too), and
     *                   at their goal kick this far out of their penalty area, m
     */
    public record SetPieces(boolean enabled, double keepOut, double tolerance, double halfMargin) {
        public static final SetPieces DEFAULT = new SetPieces(true, 2.6, 0.2, 0.3);
        public static final SetPieces OFF = new SetPieces(false, 2.6, 0.2, 0.3);
    }

    public static final AgentConfig DEFAULT = new AgentConfig(Head.DEFAULT, Beliefs.DEFAULT, Walk.DEFAULT,
            Kick.DEFAULT, Obstacles.DEFAULT, Keeper.DEFAULT, Fallback.DEFAULT, Approach.DEFAULT, KickOff.DEFAULT, Charging.DEFAULT,
            SetPieces.DEFAULT);

    public AgentConfig {
        if (head == null || beliefs == null || walk == null || kick == null || obstacles == null
                || keeper == null || fallback == null || approach == null || kickOff == null || charging == null || setPieces == null) {
            throw new IllegalArgumentException("every part of the agent config is required");
        }
    }

    public AgentConfig withKick(Kick k) { return new AgentConfig(head, beliefs, walk, k, obstacles, keeper, fallback, approach, kickOff, charging, setPieces); }

    public AgentConfig withKeeper(Keeper k) { return new AgentConfig(head, beliefs, walk, kick, obstacles, k, fallback, approach, kickOff, charging, setPieces); }

    public AgentConfig withApproach(Approach a) { return new AgentConfig(head, beliefs, walk, kick, obstacles, keeper, fallback, a, kickOff, charging, setPieces); }

    public AgentConfig withFallback(Fallback f) { return new AgentConfig(head, beliefs, walk, kick, obstacles, keeper, f, approach, kickOff, charging, setPieces); }

    public AgentConfig withCharging(Charging c) { return new AgentConfig(head, beliefs, walk, kick, obstacles, keeper, fallback, approach, kickOff, c, setPieces); }

    public AgentConfig withSetPieces(SetPieces p) { return new AgentConfig(head, beliefs, walk, kick, obstacles, keeper, fallback, approach, kickOff, charging, p); }

    public AgentConfig withKickOff(KickOff k) { return new AgentConfig(head, beliefs, walk, kick, obstacles, keeper, fallback, approach, k, charging, setPieces); }

    /** The defaults with the leg geometry of this robot type (the camera height for Track Object) and its kicks. */
    public static AgentConfig forRobotType(int type) {
        Head h = new Head(Head.DEFAULT.panAmplitudeDeg(), Head.DEFAULT.panPeriodSeconds(), Head.DEFAULT.scanPitchDownDeg(),
                NaoModel.ofType(type), Head.DEFAULT.leadSeconds());
        return new AgentConfig(h, Beliefs.DEFAULT, Walk.DEFAULT, type == 4 ? Kick.TYPE_4 : Kick.DEFAULT, Obstacles.DEFAULT, Keeper.DEFAULT, Fallback.DEFAULT, Approach.DEFAULT, KickOff.DEFAULT, Charging.DEFAULT, SetPieces.DEFAULT);
    }
}

package phalanx.coordination;

/**
 * Every constant of the team coordination (thesis chapter 5), with the thesis value as default.
 * Where the thesis gives no number (margins, formation offsets) the value is ours and says so.
 *
 * @param goalkeeperId          5.5: uniform number of the goalkeeper, who is also the coordinator
 * @param activeCount           5.5: size of the Active subset (the players nearest the ball)
 * @param ballClusterThreshold  5.4: metres within which a ball observation joins a cluster
 * @param ballClusterExponent   5.4: a cluster's weight is its size to this power (|s|^3)
 * @param activePositions       5.7: the candidate rings around the ball
 * @param onBall                5.8: the on-ball choice
 * @param activeWeights         5.8: weights of the five features of the active cost
 * @param collision             5.8, Figure 5.8: the potential-collision feature
 * @param supportWeights        5.12: weights of distance and collisions in the support cost
 * @param formation             5.9: the formation's offsets
 */
public record CoordinationConfig(int goalkeeperId, int activeCount,
                                 double ballClusterThreshold, double ballClusterExponent,
                                 ActivePositionsConfig activePositions, OnBallConfig onBall,
                                 ActiveWeights activeWeights, CollisionConfig collision,
                                 SupportWeights supportWeights, FormationConfig formation) {

    /** The thesis's values everywhere. */
    public static final CoordinationConfig THESIS = new CoordinationConfig(
            1, 3,          // 5.5: player 1 is the goalkeeper; three active players
            1.0, 3.0,      // 5.4: 1 m clusters, weight |s|^3
            ActivePositionsConfig.THESIS, OnBallConfig.THESIS, ActiveWeights.THESIS,
            CollisionConfig.THESIS, SupportWeights.THESIS, FormationConfig.DEFAULT);

    public CoordinationConfig {
        if (activeCount < 1 || activeCount > 3)
            throw new IllegalArgumentException("activeCount must be 1..3 (Algorithm 4 maps the on-ball player plus up to two), got " + activeCount);
        if (!(ballClusterThreshold > 0)) throw new IllegalArgumentException("ballClusterThreshold must be > 0, got " + ballClusterThreshold);
    }

    public CoordinationConfig withSupportWeights(SupportWeights w) {
        return new CoordinationConfig(goalkeeperId, activeCount, ballClusterThreshold, ballClusterExponent,
                activePositions, onBall, activeWeights, collision, w, formation);
    }

    public CoordinationConfig withOnBall(OnBallConfig o) {
        return new CoordinationConfig(goalkeeperId, activeCount, ballClusterThreshold, ballClusterExponent,
                activePositions, o, activeWeights, collision, supportWeights, formation);
    }

    /**
     * 5.7. Defensive rings: 12 at 1 m and 12 at 1.5 m, 30° apart. Offensive rings: 12 at 2 m, 30° apart,
     * and 24 at max{3, (|x|+|y|)/(L/2+W/2)} m, 15° apart. The thesis drops positions "outside or near"
     * the field's limits without a number: {@code fieldMargin} (ours) is how far inside the lines a
     * candidate must lie. Up to {@code keep} candidates survive the utility filter.
     */
    public record ActivePositionsConfig(double defensiveInner, double defensiveOuter, int defensiveCount,
                                        double offensiveInner, int offensiveInnerCount,
                                        double offensiveOuterMin, int offensiveOuterCount,
                                        double fieldMargin, int keep) {
        public static final ActivePositionsConfig THESIS =
                new ActivePositionsConfig(1.0, 1.5, 12, 2.0, 12, 3.0, 24, 0.3, 9);
    }

    /**
     * 5.8: Value_i = d_i + a·θ_i (a = 0.01 per degree); the previous on-ball player's value is lowered by
     * {@code hysteresis} (1) so near-ties do not flip the choice every round.
     */
    public record OnBallConfig(double angleWeight, double hysteresis) {
        public static final OnBallConfig THESIS = new OnBallConfig(0.01, 1.0);
    }

    /** 5.8: (w_d, w_c, w_u, w_t, w_h) = (1, 1, 1/7, 1, 1). */
    public record ActiveWeights(double distance, double collision, double utility, double closeTargets,
                                double stretch) {
        public static final ActiveWeights THESIS = new ActiveWeights(1, 1, 1.0 / 7, 1, 1);
    }

    /**
     * 5.8, Figure 5.8: crossing routes cost {@code likely} (100) when the crossing point is nearly
     * equidistant from the two starts (|d1 - d2| within {@code equidistance}, 1.5 m), {@code unlikely} (2)
     * otherwise; routes that do not cross cost 0.
     */
    public record CollisionConfig(double likely, double unlikely, double equidistance) {
        public static final CollisionConfig THESIS = new CollisionConfig(100, 2, 1.5);
    }

    /** 5.12: (w_d, w_c) = (1, 1). */
    public record SupportWeights(double distance, double collision) {
        public static final SupportWeights THESIS = new SupportWeights(1, 1);
    }

    /**
     * 5.9. The thesis gives the shape of the formation (Tables 5.1, 5.2; Figures 5.9-5.11 are lost) and
     * two numbers: the Defender Center stands 2 to 3 m from our goal on the goal-ball line, in
     * proportion to that line's length. Every other offset here is ours, in metres.
     *
     * @param defenderNear      DC's distance from our goal when the ball is on the goal (thesis: 2)
     * @param defenderFar       DC's distance when the ball is as far as it gets (thesis: 3)
     * @param defenderSpread    DL and DR stand this far to either side of DC, across the goal-ball line
     * @param defenderStepUp    ... and this far up the goal-ball line
     * @param forwardBehind     FC stands this far behind the ball (towards our goal)
     * @param forwardMinX       no forward stands below this x ("close to the middle of the field")
     * @param wingBase          FL/FR distance from FC near the middle; grows by {@code wingGrowth} ...
     * @param wingGrowth        ... times the ball's progress (0 at our goal line, 1 at theirs)
     * @param wingAngle         FL/FR bearing from FC, degrees from +x, before the turn towards their goal
     * @param supportBehind     11 players: FS this far behind FC, MC this far behind FS
     * @param midfieldAhead     9 players, ball in our half: ML/MR this far ahead of DC
     * @param midfieldSpread    ML/MR this far either side of their centre
     * @param midfieldAngle     11 players: ML/MR bearing from MC, degrees from +x, before the turn towards their goal
     * @param midfieldBehindForwards 9 players, ball in their half: ML/MR this far behind FC
     * @param goalkeeperDepth   GK this far in front of our goal line
     * @param inset             every formation position stays this far inside the lines
     */
    public record FormationConfig(double defenderNear, double defenderFar, double defenderSpread,
                                  double defenderStepUp, double forwardBehind, double forwardMinX,
                                  double wingBase, double wingGrowth, double wingAngle,
                                  double supportBehind, double midfieldAhead, double midfieldSpread, double midfieldAngle,
                                  double midfieldBehindForwards, double goalkeeperDepth, double inset) {
        public static final FormationConfig DEFAULT = new FormationConfig(
                2.0, 3.0,   // thesis 5.9
                1.8, 0.5, 0.6, -1.0, 2.0, 1.5, 115, 2.0, 3.0, 2.5, 95, 3.0, 0.5, 0.5);
    }
}

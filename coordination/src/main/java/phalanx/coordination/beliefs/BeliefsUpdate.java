package phalanx.coordination.beliefs;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;
import phalanx.localization.team.BallFusion;

/**
 * Phase 1 of Algorithm 3, "Update Coordination Beliefs" (thesis 5.4): fuses the players' reports into
 * one global ball, each player's position and each player's distance to that ball.
 * <ul>
 * <li>C, L: the reported position; the distance is measured to the global ball.</li>
 * <li>B: the position is inferred from the global ball and the reported distance and bearing; the
 *     distance is the reported one. The bearing is body-relative, so the body's heading is needed: the
 *     report's heading if it has one, otherwise 0° (facing the opponent goal, how players usually stand);
 *     the thesis does not say which it assumed.</li>
 * <li>X: no position, infinite distance.</li>
 * </ul>
 * Bad reports never throw: each is dropped or downgraded with one line in {@link GlobalBeliefs#warnings()}.
 */
public final class BeliefsUpdate {
    /** A ball observation farther than this outside the lines is treated as a misperception. */
    static final double BALL_OUTSIDE_LIMIT = 3.0;

    private BeliefsUpdate() {}

    /**
     * @param previousBall the ball of the previous round, used when nobody sees the ball and the
     *                     coordinator has no fallback either (may be null)
     */
    public static GlobalBeliefs update(TeamBeliefs beliefs, double clusterThreshold, double clusterExponent,
                                       Vector2 previousBall) {
        FieldSpec field = beliefs.field();
        List<String> warnings = new ArrayList<>();
        Map<Integer, PlayerReport> byId = new TreeMap<>();
        for (PlayerReport r : beliefs.reports()) {
            if (r == null) { warnings.add("null report dropped"); continue; }
            if (r.id() < 1 || r.id() > field.players()) {
                warnings.add("report from player " + r.id() + " dropped: uniform numbers are 1.." + field.players());
                continue;
            }
            if (byId.put(r.id(), validated(r, field, warnings)) != null)
                warnings.add("player " + r.id() + " reported twice: the later report is used");
        }

        List<Vector2> observations = new ArrayList<>();
        for (PlayerReport r : byId.values())
            if (r.type() == ReportType.C && !r.fallen()) observations.add(r.ball());
        Vector2 ball = new BallFusion(clusterThreshold, clusterExponent).fuse(observations);
        if (ball == null) {
            Vector2 fb = beliefs.fallbackBall();
            if (fb != null && fb.isFinite()) ball = fb;
            else if (previousBall != null && previousBall.isFinite()) ball = previousBall;
            else {
                ball = Vector2.ZERO;
                warnings.add("nobody knows where the ball is: assuming the centre spot");
            }
        }

        List<PlayerBelief> players = new ArrayList<>(byId.size());
        for (PlayerReport r : byId.values()) {
            switch (r.type()) {
                case C, L -> players.add(new PlayerBelief(r.id(), r.type(), r.self().position(), r.self().thetaDeg(),
                        r.self().position().distanceTo(ball), r.fallen()));
                case B -> {
                    double heading = Double.isFinite(r.headingDeg()) ? r.headingDeg() : 0.0;
                    Vector2 pos = ball.minus(Vector2.polar(r.ballDistance(), heading + r.ballBearingDeg()));
                    players.add(new PlayerBelief(r.id(), ReportType.B, pos, r.headingDeg(), r.ballDistance(), r.fallen()));
                }
                case X -> players.add(new PlayerBelief(r.id(), ReportType.X, null, Double.NaN,
                        Double.POSITIVE_INFINITY, r.fallen()));
            }
        }
        return new GlobalBeliefs(field, ball, observations.size(), players, warnings);
    }

    /** The report with the fields its type needs, or a weaker type when they are missing or not finite. */
    private static PlayerReport validated(PlayerReport r, FieldSpec field, List<String> warnings) {
        int id = r.id();
        boolean selfOk = r.self() != null && Double.isFinite(r.self().x()) && Double.isFinite(r.self().y())
                && Double.isFinite(r.self().thetaDeg());
        switch (r.type()) {
            case C -> {
                boolean ballOk = r.ball() != null && r.ball().isFinite();
                if (ballOk && !field.contains(r.ball(), BALL_OUTSIDE_LIMIT)) {
                    warnings.add("player " + id + " sees the ball at " + fmt(r.ball())
                            + ", more than " + BALL_OUTSIDE_LIMIT + " m outside the field: ball ignored");
                    ballOk = false;
                }
                if (selfOk && ballOk) return r;
                if (selfOk) {
                    if (r.ball() == null || !r.ball().isFinite())
                        warnings.add("player " + id + " sent type C without a finite ball: used as type L");
                    return new PlayerReport(id, ReportType.L, r.self(), null, Double.NaN, Double.NaN, Double.NaN, r.fallen());
                }
                warnings.add("player " + id + " sent type C without a finite position: used as type X");
            }
            case L -> {
                if (selfOk) return r;
                warnings.add("player " + id + " sent type L without a finite position: used as type X");
            }
            case B -> {
                if (Double.isFinite(r.ballDistance()) && r.ballDistance() >= 0 && Double.isFinite(r.ballBearingDeg()))
                    return r;
                warnings.add("player " + id + " sent type B with distance " + r.ballDistance() + " and bearing "
                        + r.ballBearingDeg() + ": used as type X");
            }
            case X -> { return r; }
        }
        return new PlayerReport(id, ReportType.X, null, null, Double.NaN, Double.NaN, Double.NaN, r.fallen());
    }

    private static String fmt(Vector2 v) { return String.format("(%.2f, %.2f)", v.x(), v.y()); }
}

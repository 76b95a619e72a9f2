package phalanx.coordination;

import java.util.ArrayList;
import java.util.List;
import phalanx.coordination.beliefs.PlayerReport;
import phalanx.coordination.beliefs.TeamBeliefs;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/** Team situations for tests: every player reports type C with the same ball unless told otherwise. */
final class Scenarios {
    private Scenarios() {}

    /** Eleven players in a kick-off-like spread, ball where given. */
    static TeamBeliefs eleven(Vector2 ball) {
        double[][] xy = {{-14, 0}, {-10, 4}, {-11, 0}, {-10, -4}, {-6, 6}, {-6, 0}, {-6, -6},
                {-3, 0}, {-1, 5}, {-1, 0}, {-1, -5}};
        List<PlayerReport> r = new ArrayList<>();
        for (int i = 0; i < 11; i++) r.add(PlayerReport.complete(i + 1, new Pose2(xy[i][0], xy[i][1], 0), ball));
        return new TeamBeliefs(FieldSpec.V066, r);
    }

    static TeamBeliefs replace(TeamBeliefs t, PlayerReport report) {
        List<PlayerReport> r = new ArrayList<>(t.reports());
        r.removeIf(x -> x.id() == report.id());
        r.add(report);
        return new TeamBeliefs(t.field(), r, t.fallbackBall());
    }
}

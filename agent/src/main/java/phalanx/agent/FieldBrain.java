package phalanx.agent;

import phalanx.agent.action.FieldPlayerBehaviour;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.team.TeamChannel;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.formation.FormationGenerator;
import phalanx.coordination.formation.Role;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

/**
 * A field player: carries out the coordinator's last order (thesis 5.3); when the coordinator is
 * quiet, acts on its own beliefs with its formation spot for the ball it believes in as home.
 */
final class FieldBrain implements Brain {
    private final FieldPlayerBehaviour behaviour;
    private final Role role;
    private final CoordinationConfig coordination;
    // The home spot of the last ball: the believed ball changes only with vision (every third
    // cycle), and the whole formation is built to read one spot of it.
    private Vector2 homeBall;
    private FieldSpec homeField;
    private Vector2 home;

    FieldBrain(FieldPlayerBehaviour behaviour, int unum, int players, CoordinationConfig coordination) {
        this.behaviour = behaviour;
        this.role = Role.forPlayers(players).get(unum - 1);
        this.coordination = coordination;
    }

    @Override public Decision decide(Situation s, TeamChannel channel) {
        behaviour.order(channel.order());
        Vector2 ball = s.belief().ballGlobal() != null ? s.belief().ballGlobal() : Vector2.ZERO;
        if (!ball.equals(homeBall) || s.field() != homeField) {
            home = FormationGenerator.generate(ball, s.field(), coordination.formation()).position(role);
            homeBall = ball;
            homeField = s.field();
        }
        return behaviour.decide(s, channel.coordinatorQuiet(), home);
    }

    @Override public Vector2 target() {
        Action a = behaviour.order();
        return a != null && a.id() == ActionId.WALK_TO_COORDINATE ? new Vector2(a.x(), a.y()) : null;
    }
}

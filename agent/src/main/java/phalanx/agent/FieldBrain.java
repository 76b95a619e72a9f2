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
import phalanx.localization.field.Vector2;

/**
 * A field player: carries out the coordinator's last order (thesis 5.3); when the coordinator is
 * quiet, acts on its own beliefs with its formation spot for the ball it believes in as home.
 */
final class FieldBrain implements Brain {
    private final FieldPlayerBehaviour behaviour;
    private final Role role;
    private final CoordinationConfig coordination;

    FieldBrain(FieldPlayerBehaviour behaviour, int unum, int players, CoordinationConfig coordination) {
        this.behaviour = behaviour;
        this.role = Role.forPlayers(players).get(unum - 1);
        this.coordination = coordination;
    }

    @Override public Decision decide(Situation s, TeamChannel channel) {
        behaviour.order(channel.order());
        Vector2 ball = s.belief().ballGlobal() != null ? s.belief().ballGlobal() : Vector2.ZERO;
        Vector2 home = FormationGenerator.generate(ball, s.field(), coordination.formation()).position(role);
        return behaviour.decide(s, channel.coordinatorQuiet(), home);
    }

    @Override public Vector2 target() {
        Action a = behaviour.order();
        return a != null && a.id() == ActionId.WALK_TO_COORDINATE ? new Vector2(a.x(), a.y()) : null;
    }
}

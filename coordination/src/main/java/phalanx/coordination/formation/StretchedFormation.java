package phalanx.coordination.formation;

import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.MjField;
import phalanx.model.field.Vector2;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The thesis formation (5.9, {@link FormationGenerator}) on a field of another size: generated for the ball's
 * place on the 30 x 20 m SimSpark field, where its distances were tuned, and stretched to the other field
 * along each axis, keeping only the roles of the team size (rcssservermj's 55 x 36 m field, 7 players: our choice,
 * there is no thesis formation for it).
 */
public final class StretchedFormation {
    private final MjField field;
    private final FormationConfig config;
    private final List<Role> roles;
    private final double sx, sy;

    public StretchedFormation(MjField field, FormationConfig config) {
        this.field = field;
        this.config = config;
        this.roles = Role.forPlayers(field.players());
        this.sx = field.length() / FieldSpec.V066.length();
        this.sy = field.width() / FieldSpec.V066.width();
    }

    /** The formation for the ball at this place (own frame, metres on the bigger field). */
    public Formation generate(Vector2 ball) {
        Vector2 b = ball.isFinite() ? new Vector2(ball.x() / sx, ball.y() / sy) : Vector2.ZERO;
        Formation small = FormationGenerator.generate(b, FieldSpec.V066, config);
        Map<Role, Vector2> p = new EnumMap<>(Role.class);
        for (Role r : roles) {
            Vector2 q = small.position(r);
            p.put(r, new Vector2(q.x() * sx, q.y() * sy));
        }
        return new Formation(p);
    }

    /** Player n's role (n from 1). */
    public Role role(int unum) { return roles.get(unum - 1); }

    public MjField field() { return field; }
}

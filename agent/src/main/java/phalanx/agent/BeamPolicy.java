package phalanx.agent;

import phalanx.comm.perception.PlayMode;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.formation.Formation;
import phalanx.coordination.formation.FormationGenerator;
import phalanx.coordination.formation.Role;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;

/**
 * Beam to the kick-off spot — the formation of thesis 5.9 for the ball on the centre spot, player n
 * taking the n-th role (GK, DL, DC, DR, ML, MC, MR, FS, FL, FC, FR) — whenever the play mode allows it: before each kick-off and after each
 * goal (both halves); the kick-off partner of {@link AgentConfig.KickOff} beams beside the ball instead. Once per such play mode, and again every 2 s while it lasts, because a beam
 * sent in the cycle the mode changes can be refused.
 */
final class BeamPolicy {
    private static final double REPEAT_S = 2.0;
    private final List<Role> roles;
    private final Formation kickOff;
    private final AgentConfig.KickOff kickOffPlay;
    private PlayMode lastMode;
    private double lastBeam = Double.NEGATIVE_INFINITY;

    BeamPolicy(FieldSpec field, CoordinationConfig config, AgentConfig.KickOff kickOffPlay) {
        this.kickOffPlay = kickOffPlay;
        roles = Role.forPlayers(field.players());
        kickOff = FormationGenerator.generate(Vector2.ZERO, field, config.formation());
    }

    /** The beam to send this cycle, or null. */
    Pose2 beam(PlayMode mode, double now, int unum) {
        if (mode == null || !mode.allowsBeam() || unum < 1 || unum > roles.size()) {
            lastMode = mode;
            return null;
        }
        boolean newMode = mode != lastMode;
        lastMode = mode;
        if (!newMode && now - lastBeam < REPEAT_S) return null;
        lastBeam = now;
        // The kick-off partner waits beside the ball (action.KickOffPlay); in their kick-off the
        // referee moves it out of the centre circle, as it does the formation's centre forward.
        if (kickOffPlay.enabled() && unum == kickOffPlay.partner()) return new Pose2(kickOffPlay.partnerX(), kickOffPlay.partnerY(), 0);
        Vector2 spot = kickOff.position(roles.get(unum - 1));
        return new Pose2(spot.x(), spot.y(), 0);
    }
}

package phalanx.agent;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;
import phalanx.coordination.CoordinationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;

import static org.junit.jupiter.api.Assertions.*;

class BeamPolicyTest {
    private static final FieldSpec FIELD = FieldSpec.forPlayers(11);

    @Test
    void theKickOffPartnerBeamsBesideTheBallAndTheOthersToTheirFormationSpots() {
        AgentConfig.KickOff k = AgentConfig.KickOff.TAP;
        BeamPolicy with = new BeamPolicy(FIELD, CoordinationConfig.THESIS, k);
        BeamPolicy without = new BeamPolicy(FIELD, CoordinationConfig.THESIS, AgentConfig.KickOff.OFF);
        Pose2 partner = with.beam(PlayMode.BEFORE_KICK_OFF, 0, k.partner());
        assertEquals(k.partnerX(), partner.x(), 1e-9);
        assertEquals(k.partnerY(), partner.y(), 1e-9);
        Pose2 formation = without.beam(PlayMode.BEFORE_KICK_OFF, 0, k.partner());
        assertTrue(formation.position().distanceTo(partner.position()) > 1, "the formation's spot is elsewhere: " + formation);
        assertEquals(without.beam(PlayMode.BEFORE_KICK_OFF, 0, k.taker()), with.beam(PlayMode.BEFORE_KICK_OFF, 0, k.taker()),
                "the taker keeps its formation spot (the nearest to the ball)");
        assertNull(with.beam(PlayMode.PLAY_ON, 5, k.partner()), "no beam in PlayOn");
    }
}

package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.decide.Move;

import static org.junit.jupiter.api.Assertions.*;

/** The charging rule as the server applies it (AgentConfig.Charging): when walking into an opponent slows us. */
class ChargingGuardTest {
    private static final ChargingGuard GUARD = new ChargingGuard(AgentConfig.DEFAULT);
    private static final Move FULL = new Move.Walk(0.2, false);

    @Test
    void aWalkIntoAnOpponentCloseAheadAwayFromTheBallIsSlowedAndKeepsItsLean() {
        World w = World.at(0, 0, 0).opponentAt(4, 0.7, 0.1).ballAt(6, 0);
        assertEquals(new Move.Walk(0.2, true), GUARD.limit(w.situation(), FULL));
        Move.Omni omni = new Move.Omni(1, 0.3, -0.2);
        assertEquals(new Move.Omni(0.4, 0.3, -0.2), GUARD.limit(w.situation(), omni), "forward share cut, side and turn kept");
    }

    @Test
    void anOpponentBesideOrBehindOrFarIsNoReasonToSlow() {
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).opponentAt(4, 0, 0.8).ballAt(6, 0).situation(), FULL), "beside: 90 deg off");
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).opponentAt(4, -0.6, 0).ballAt(6, 0).situation(), FULL), "behind");
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).opponentAt(4, 1.4, 0).ballAt(6, 0).situation(), FULL), "1.4 m ahead");
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).teammateAt(4, 0.6, 0).ballAt(6, 0).situation(), FULL), "a teammate");
    }

    @Test
    void nearTheBallOnlyTheOneFartherFromItIsSlowed() {
        // the ball 0.4 m ahead, the opponent beyond it 0.56 m from it: we are the nearer one and head for it
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).ballAt(0.4, 0).opponentAt(4, 0.95, 0.1).situation(), FULL));
        // the opponent between us and the ball, nearer to it: walking on is our foul
        assertEquals(new Move.Walk(0.2, true), GUARD.limit(World.at(0, 0, 0).ballAt(0.9, 0).opponentAt(4, 0.6, 0).situation(), FULL));
    }

    @Test
    void onTheBallDribblingWeKeepGoingAndSlowOrOtherMovesAreLeftAlone() {
        assertSame(FULL, GUARD.limit(World.at(0, 0, 0).ballAt(0.2, 0).opponentAt(4, 0.5, 0).situation(), FULL), "we touch the ball: immune");
        World w = World.at(0, 0, 0).opponentAt(4, 0.6, 0).ballAt(6, 0);
        Move slow = new Move.Walk(0, true), turn = new Move.Turn(true, 0.5), kick = new Move.Kick(false, false);
        assertSame(slow, GUARD.limit(w.situation(), slow));
        assertSame(turn, GUARD.limit(w.situation(), turn));
        assertSame(kick, GUARD.limit(w.situation(), kick));
        assertSame(FULL, new ChargingGuard(AgentConfig.DEFAULT.withCharging(AgentConfig.Charging.OFF)).limit(w.situation(), FULL), "switched off");
    }

    @Test
    void anOpponentSeenLongAgoIsForgotten() {
        World w = World.at(0, 0, 0).ballAt(6, 0);
        w.opponents.add(new phalanx.localization.belief.PlayerBelief("Them", 9, w.now - 5, new phalanx.model.field.Vector2(0.6, 0),
                new phalanx.model.field.Vector2(0.6, 0), new phalanx.model.field.Vector2[phalanx.comm.perception.BodyPart.COUNT], null));
        assertSame(FULL, GUARD.limit(w.situation(), FULL));
    }
}

package phalanx.coordination;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;

class ModeTest {
    @Test
    void waitBeforeKickOffAndAfterGoals() {
        assertEquals(Mode.WAIT, Mode.of(PlayMode.BEFORE_KICK_OFF, Side.LEFT, false));
        assertEquals(Mode.WAIT, Mode.of(PlayMode.GOAL_LEFT, Side.RIGHT, false));
        assertEquals(Mode.WAIT, Mode.of(PlayMode.GAME_OVER, Side.RIGHT, true));
    }

    @Test
    void activeInPlayOnAndOurSetPieces() {
        assertEquals(Mode.ACTIVE, Mode.of(PlayMode.PLAY_ON, Side.LEFT, false));
        assertEquals(Mode.ACTIVE, Mode.of(PlayMode.KICK_OFF_LEFT, Side.LEFT, false));
        assertEquals(Mode.ACTIVE, Mode.of(PlayMode.CORNER_KICK_RIGHT, Side.RIGHT, false));
        assertEquals(Mode.ACTIVE, Mode.of(PlayMode.UNKNOWN, Side.RIGHT, false));
    }

    @Test
    void supportInTheirSetPiecesOrWhenOurGoalkeeperHasTheBall() {
        assertEquals(Mode.SUPPORT, Mode.of(PlayMode.KICK_OFF_RIGHT, Side.LEFT, false));
        assertEquals(Mode.SUPPORT, Mode.of(PlayMode.GOAL_KICK_LEFT, Side.RIGHT, false));
        assertEquals(Mode.SUPPORT, Mode.of(PlayMode.PLAY_ON, Side.LEFT, true));
        assertEquals(Mode.SUPPORT, Mode.of(PlayMode.KICK_IN_LEFT, Side.LEFT, true));
    }

    @Test
    void offsideIsTheOtherTeamsFreeKick() {
        // offside_left: the left team was offside, the right team kicks.
        assertEquals(Mode.SUPPORT, Mode.of(PlayMode.OFFSIDE_LEFT, Side.LEFT, false));
        assertEquals(Mode.ACTIVE, Mode.of(PlayMode.OFFSIDE_LEFT, Side.RIGHT, false));
    }

    @Test
    void missingSideIsRefusedWithAMessage() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Mode.of(PlayMode.PLAY_ON, null, false));
        assertEquals("play mode and side are needed, got PLAY_ON, null", e.getMessage());
    }
}

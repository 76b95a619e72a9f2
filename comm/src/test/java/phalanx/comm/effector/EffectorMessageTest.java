package phalanx.comm.effector;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Joint;

import static org.junit.jupiter.api.Assertions.*;

class EffectorMessageTest {

    @Test
    void handshakeMessagesMatchTheRecordedOnes() {
        // S1_effectors.txt lines 1-2
        assertEquals("(scene rsg/agent/nao/nao_hetero.rsg 0)", EffectorMessage.scene(0));
        assertEquals("(scene rsg/agent/nao/nao.rsg)", EffectorMessage.scene(-1));
        assertEquals("(init (unum 1)(teamname Probe))(syn)", EffectorMessage.init(1, "Probe"));
        assertThrows(IllegalArgumentException.class, () -> EffectorMessage.scene(5));
        assertThrows(IllegalArgumentException.class, () -> EffectorMessage.init(1, "two words"));
        assertThrows(IllegalArgumentException.class, () -> EffectorMessage.init(12, "T"));
    }

    @Test
    void cycleMessageWithBeamHingesSayAndSyn() {
        EffectorMessage m = new EffectorMessage();
        m.reset().beam(-5, 2, 0).syn();
        assertEquals("(beam -5 2 0)(syn)", m.toString()); // S1_effectors.txt line 3
        m.reset().hinge(Joint.LLJ5, -2).hinge(Joint.RLJ5, -2).syn();
        assertEquals("(lle5 -2)(rle5 -2)(syn)", m.toString()); // S3, k = 75
        m.reset().hinge(Joint.HJ1, 0.12345).hinge(Joint.RLJ7, -0.005).say("hello1").syn();
        assertEquals("(he1 0.1235)(rle7 -0.005)(say hello1)(syn)", m.toString());
    }

    @Test
    void sayRefusesWhatTheServerWouldDrop() {
        EffectorMessage m = new EffectorMessage();
        m.say("abcdefghijklmnopqrst"); // 20: delivered in S4
        IllegalArgumentException tooLong = assertThrows(IllegalArgumentException.class, () -> m.say("abcdefghijklmnopqrstu"));
        assertTrue(tooLong.getMessage().contains("21 characters"), tooLong.getMessage());
        IllegalArgumentException space = assertThrows(IllegalArgumentException.class, () -> m.say("a b"));
        assertTrue(space.getMessage().contains("' ' at position 1"), space.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.say("a(b"));
        assertThrows(IllegalArgumentException.class, () -> m.say(""));
        assertThrows(IllegalArgumentException.class, () -> m.say("\u00e9"));
        assertNull(EffectorMessage.sayProblem("x=1.5;y=-2"));
    }

    @Test
    void nonFiniteVelocityIsRefused() {
        EffectorMessage m = new EffectorMessage();
        assertThrows(IllegalArgumentException.class, () -> m.hinge(Joint.HJ1, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> m.beam(Double.POSITIVE_INFINITY, 0, 0));
    }
}

package phalanx.comm.mj;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class MjActionsTest {
    @Test
    void buildsInitBeamAndJoints() {
        assertEquals("(init T1 Phalanx 1)", MjActions.init("Phalanx", 1));
        assertEquals("(beam -3 0 90)", MjActions.beam(-3, 0, 90));
        MjActions a = new MjActions();
        assertEquals("(syn)", a.build());
        assertEquals("(lle1 10.5 0 20 1 0)(he1 -1 0 5 0.1 0)",
                a.joint("lle1", 10.5, 0, 20, 1, 0).joint("he1", -1, -0.0, 5, 0.1, 0).build());
        assertEquals(23, MjActions.T1_ACTUATORS.size());
        assertThrows(IllegalArgumentException.class, () -> a.joint("hj1", 0, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> MjActions.beam(Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> MjActions.init("a b", 1));
    }

    @Test
    void saysUpToTenBytesAsBase64AtFullVolume() {
        MjActions a = new MjActions();
        assertEquals("(SPK say 100 AAECAwQFBgcICQ==)", a.say(new byte[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}).build());
        assertEquals("(SPK say 100 +/8=)(lle1 1 0 2 0 0)", a.say(new byte[] {(byte) 0xfb, (byte) 0xff}).joint("lle1", 1, 0, 2, 0, 0).build());
        assertThrows(IllegalArgumentException.class, () -> a.say(new byte[11]));
        assertThrows(IllegalArgumentException.class, () -> a.say(new byte[0]));
        assertThrows(IllegalArgumentException.class, () -> a.say(null));
        assertEquals("(syn)", a.build());
    }
}

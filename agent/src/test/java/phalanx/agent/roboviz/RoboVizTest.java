package phalanx.agent.roboviz;

import org.junit.jupiter.api.Test;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Receives the drawer's UDP packets on loopback and decodes them by the RoboViz draw protocol. */
class RoboVizTest {

    @Test
    void shapesAndSwapArriveDecodable() throws Exception {
        try (DatagramSocket rx = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            rx.setSoTimeout(2000);
            RoboViz rv = RoboViz.to("127.0.0.1:" + rx.getLocalPort());
            assertTrue(rv.on());
            rv.circle(-1.5, 2.25, 0.3, 2, 0xff8000, "animated.phalanx.L.1.beliefs")
              .line(0, 0, 0, 12.5, -3, 0.1, 3, 0x00ff00, "animated.phalanx.L.1.target")
              .annotation("GK", -14, 0, 1, 0xffffff, "animated.phalanx.L.1.roles")
              .swap("animated.phalanx.L.1");
            rv.flush();
            DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
            rx.receive(p);
            Decoder d = new Decoder(p.getData(), p.getLength());
            List<String> cmds = new ArrayList<>();
            while (d.more()) cmds.add(d.command());
            assertEquals(List.of(
                    "circle -1.500 2.2500 0.3000 2.0000 255,128,0 animated.phalanx.L.1.beliefs",
                    "line 0.0000 0.0000 0.0000 12.500 -3.000 0.1000 3.0000 0,255,0 animated.phalanx.L.1.target",
                    "annotation -14.00 0.0000 1.0000 255,255,255 GK animated.phalanx.L.1.roles",
                    "swap animated.phalanx.L.1"), cmds);
        }
    }

    @Test
    void manyShapesAreSplitIntoDatagramsBetweenCommands() throws Exception {
        try (DatagramSocket rx = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            rx.setSoTimeout(2000);
            RoboViz rv = RoboViz.to("127.0.0.1:" + rx.getLocalPort());
            for (int i = 0; i < 100; i++) rv.sphere(i, -i, 0.1, 0.05, 0x0000ff, "animated.phalanx.R.9.opponents");
            rv.flush();
            int spheres = 0, packets = 0;
            while (spheres < 100) {
                DatagramPacket p = new DatagramPacket(new byte[4096], 4096);
                rx.receive(p);
                packets++;
                assertTrue(p.getLength() <= RoboViz.MAX_DATAGRAM, "datagram of " + p.getLength());
                Decoder d = new Decoder(p.getData(), p.getLength());
                while (d.more()) {
                    assertTrue(d.command().startsWith("sphere"));
                    spheres++;
                }
            }
            assertEquals(100, spheres);
            assertTrue(packets > 1);
        }
    }

    @Test
    void offDrawsNothingAndBadAddressesAreNamed() {
        assertFalse(RoboViz.OFF.on());
        RoboViz.OFF.circle(0, 0, 1, 1, 0, "x").flush();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RoboViz.to("localhost:abc"));
        assertTrue(e.getMessage().contains("port must be a number"));
    }

    /** A minimal reader of the protocol, written from its description, for the test. */
    private static final class Decoder {
        private final byte[] b;
        private final int n;
        private int i;

        Decoder(byte[] b, int n) { this.b = b; this.n = n; }

        boolean more() { return i < n; }

        String command() {
            int t1 = b[i++], t2 = b[i++];
            if (t1 == 0) return "swap " + str();
            if (t1 == 2) return "annotation " + nums(3) + " " + rgb() + " " + str() + " " + str();
            return switch (t2) {
                case 0 -> "circle " + nums(4) + " " + rgb() + " " + str();
                case 1 -> "line " + nums(7) + " " + rgb() + " " + str();
                case 2 -> "point " + nums(4) + " " + rgb() + " " + str();
                case 3 -> "sphere " + nums(4) + " " + rgb() + " " + str();
                default -> throw new AssertionError("unknown shape " + t2);
            };
        }

        private String nums(int k) {
            StringBuilder sb = new StringBuilder();
            for (int j = 0; j < k; j++) {
                String s = new String(b, i, 6, StandardCharsets.US_ASCII);
                Float.parseFloat(s); // must be a readable number
                sb.append(j > 0 ? " " : "").append(s);
                i += 6;
            }
            return sb.toString();
        }

        private String rgb() { return (b[i++] & 0xff) + "," + (b[i++] & 0xff) + "," + (b[i++] & 0xff); }

        private String str() {
            int s = i;
            while (b[i] != 0) i++;
            return new String(b, s, i++ - s, StandardCharsets.US_ASCII);
        }
    }
}

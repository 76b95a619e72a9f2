package phalanx.comm.wire;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;

import static org.junit.jupiter.api.Assertions.*;

class FramingTest {

    @Test
    void writerAndReaderRoundTripBigEndianLength() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(out);
        w.write("(syn)");
        w.write("x".repeat(70_000));
        byte[] bytes = out.toByteArray();
        assertArrayEquals(new byte[]{0, 0, 0, 5, '(', 's', 'y', 'n', ')'}, java.util.Arrays.copyOf(bytes, 9));
        FrameReader r = new FrameReader(new ByteArrayInputStream(bytes));
        r.next();
        assertEquals("(syn)", r.text());
        r.next();
        assertEquals(70_000, r.length());
        ConnectionClosedException end = assertThrows(ConnectionClosedException.class, r::next);
        assertFalse(end.midFrame());
    }

    @Test
    void oversizedLengthIsRefusedBeforeAllocating() {
        FrameReader r = new FrameReader(new ByteArrayInputStream(new byte[]{0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff}));
        WireException e = assertThrows(WireException.class, r::next);
        assertTrue(e.getMessage().contains("exceeds the 1048576-byte limit"), e.getMessage());
    }

    @Test
    void negativeLengthIsRefused() {
        FrameReader r = new FrameReader(new ByteArrayInputStream(new byte[]{(byte) 0xff, 0, 0, 1}));
        WireException e = assertThrows(WireException.class, r::next);
        assertTrue(e.getMessage().contains("negative frame length"), e.getMessage());
    }

    @Test
    void connectionClosedInsidePayloadOrHeaderIsNamed() {
        FrameReader r = new FrameReader(new ByteArrayInputStream(new byte[]{0, 0, 0, 10, '(', 't'}));
        ConnectionClosedException e = assertThrows(ConnectionClosedException.class, r::next);
        assertTrue(e.midFrame());
        assertTrue(e.getMessage().contains("2 of 10 bytes"), e.getMessage());
        FrameReader h = new FrameReader(new ByteArrayInputStream(new byte[]{0, 0}));
        ConnectionClosedException eh = assertThrows(ConnectionClosedException.class, h::next);
        assertTrue(eh.getMessage().contains("2 of 4 bytes"), eh.getMessage());
    }

    @Test
    void slowStreamDeliveringOneByteAtATimeStillFrames() throws IOException {
        byte[] bytes = {0, 0, 0, 3, 'a', 'b', 'c'};
        InputStream trickle = new InputStream() {
            int i;
            @Override public int read() { return i < bytes.length ? bytes[i++] : -1; }
            @Override public int read(byte[] b, int off, int len) {
                if (i >= bytes.length) return -1;
                b[off] = bytes[i++];
                return 1;
            }
        };
        FrameReader r = new FrameReader(trickle);
        r.next();
        assertEquals("abc", r.text());
    }

    @Test
    void connectGivesUpWithAClearMessageWhenNothingListens() throws IOException {
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        WireException e = assertThrows(WireException.class, () -> ServerConnection.connect("127.0.0.1", port, 300));
        assertTrue(e.getMessage().contains("no server at 127.0.0.1:" + port), e.getMessage());
    }
}

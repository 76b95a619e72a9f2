package phalanx.comm.wire;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/** Writes length-prefixed frames: header and payload go out in one write. Not thread-safe. */
public final class FrameWriter {
    private final OutputStream out;
    private byte[] buffer = new byte[4096];

    public FrameWriter(OutputStream out) { this.out = out; }

    public void write(CharSequence message) throws IOException {
        int len = message.length();
        if (len > FrameReader.MAX_FRAME) throw new WireException("message of " + len + " bytes exceeds the frame limit");
        ensure(len + 4);
        for (int i = 0; i < len; i++) {
            char c = message.charAt(i);
            if (c > 0x7f) throw new WireException("non-ASCII character in message at " + i);
            buffer[4 + i] = (byte) c;
        }
        send(len);
    }

    public void write(byte[] payload, int off, int len) throws IOException {
        if (len > FrameReader.MAX_FRAME) throw new WireException("message of " + len + " bytes exceeds the frame limit");
        ensure(len + 4);
        System.arraycopy(payload, off, buffer, 4, len);
        send(len);
    }

    private void ensure(int size) {
        if (buffer.length < size) buffer = new byte[Math.max(size, buffer.length * 2)];
    }

    private void send(int len) throws IOException {
        buffer[0] = (byte) (len >>> 24);
        buffer[1] = (byte) (len >>> 16);
        buffer[2] = (byte) (len >>> 8);
        buffer[3] = (byte) len;
        out.write(buffer, 0, len + 4);
        out.flush();
    }

    static byte[] ascii(String s) { return s.getBytes(StandardCharsets.US_ASCII); }
}

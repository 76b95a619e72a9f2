package phalanx.comm.wire;

import java.io.IOException;
import java.io.InputStream;

/**
 * Reads length-prefixed frames: a 4-byte big-endian length, then that many payload bytes
 * (DESIGN.md, protocol facts). One buffer is reused for every frame, so reading allocates nothing
 * once the buffer has grown to the largest message. A length above {@link #MAX_FRAME} or below 0
 * is refused before any allocation; a stream ending inside a frame is a
 * {@link ConnectionClosedException}. Not thread-safe.
 */
public final class FrameReader {
    /** 1 MiB: a full vision message with 22 players is about 5 KiB, so anything near this is garbage. */
    public static final int MAX_FRAME = 1 << 20;

    private final InputStream in;
    private final byte[] header = new byte[4];
    private byte[] buffer = new byte[16 * 1024];
    private int length;

    public FrameReader(InputStream in) { this.in = in; }

    /** Reads the next frame; its payload is {@link #buffer()}[0, {@link #length()}). */
    public void next() throws IOException {
        int got = readFully(header, 4);
        if (got == 0) throw new ConnectionClosedException("connection closed by peer", false);
        if (got < 4) throw new ConnectionClosedException("connection closed inside a frame header (" + got + " of 4 bytes)", true);
        int len = ((header[0] & 0xff) << 24) | ((header[1] & 0xff) << 16) | ((header[2] & 0xff) << 8) | (header[3] & 0xff);
        if (len < 0) throw new WireException("negative frame length " + len);
        if (len > MAX_FRAME) throw new WireException("frame length " + len + " exceeds the " + MAX_FRAME + "-byte limit");
        if (len > buffer.length) buffer = new byte[Math.max(len, buffer.length * 2)];
        int n = readFully(buffer, len);
        if (n < len) throw new ConnectionClosedException("connection closed inside a frame (" + n + " of " + len + " bytes)", true);
        length = len;
    }

    public byte[] buffer() { return buffer; }
    public int length() { return length; }

    /** The current frame as text (allocates; for logs and tests). */
    public String text() { return new String(buffer, 0, length, java.nio.charset.StandardCharsets.ISO_8859_1); }

    private int readFully(byte[] dst, int len) throws IOException {
        int off = 0;
        while (off < len) {
            int r = in.read(dst, off, len - off);
            if (r < 0) break;
            off += r;
        }
        return off;
    }
}

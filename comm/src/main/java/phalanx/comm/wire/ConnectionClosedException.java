package phalanx.comm.wire;

/** The peer closed the connection: cleanly between frames, or in the middle of one. */
public final class ConnectionClosedException extends WireException {
    private final boolean midFrame;

    public ConnectionClosedException(String message, boolean midFrame) {
        super(message);
        this.midFrame = midFrame;
    }

    /** True when the connection ended inside a frame (after part of the length or payload). */
    public boolean midFrame() { return midFrame; }
}

package phalanx.comm.sexp;

/**
 * The one exception {@link PerceptionParser} throws: the message is not a well-formed perceptor
 * message. It names the byte offset and what was expected there.
 */
public final class MalformedMessageException extends Exception {
    private final int offset;

    public MalformedMessageException(String reason, int offset) {
        super(reason + " at byte " + offset);
        this.offset = offset;
    }

    public int offset() { return offset; }
}

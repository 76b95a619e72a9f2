package phalanx.comm.wire;

import java.io.IOException;

/** The byte stream broke the framing rules or the connection ended: the message says which. */
public class WireException extends IOException {
    public WireException(String message) { super(message); }
    public WireException(String message, Throwable cause) { super(message, cause); }
}

package phalanx.comm.perception;

/** The side a team plays on; the server decides it (first team to connect is left). */
public enum Side {
    LEFT, RIGHT;

    public Side opposite() { return this == LEFT ? RIGHT : LEFT; }
}

package phalanx.comm.perception;

/** Parts of a seen player that the server reports. */
public enum BodyPart {
    HEAD("head"), RIGHT_LOWER_ARM("rlowerarm"), LEFT_LOWER_ARM("llowerarm"),
    RIGHT_FOOT("rfoot"), LEFT_FOOT("lfoot");

    private static final BodyPart[] VALUES = values();
    public static final int COUNT = VALUES.length;
    private final String wireName;
    private final byte[] wireBytes;

    BodyPart(String wireName) {
        this.wireName = wireName;
        this.wireBytes = wireName.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    }

    public String wireName() { return wireName; }

    public static BodyPart fromBytes(byte[] b, int off, int len) {
        for (BodyPart p : VALUES) {
            if (java.util.Arrays.equals(p.wireBytes, 0, p.wireBytes.length, b, off, off + len)) return p;
        }
        return null;
    }
}

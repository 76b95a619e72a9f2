package phalanx.comm.perception;

/**
 * The eight landmarks named in See: corner flags and goal posts. The names are absolute for both
 * teams (F1L is always at field (-15, 10)); localization owns their coordinates.
 */
public enum Landmark {
    F1L, F2L, F1R, F2R, G1L, G2L, G1R, G2R;

    private static final Landmark[] VALUES = values();
    public static final int COUNT = VALUES.length;

    public boolean isGoalPost() { return name().charAt(0) == 'G'; }

    public static Landmark byIndex(int i) { return VALUES[i]; }

    /** Decodes a name from message bytes without allocating, or returns null. */
    public static Landmark fromBytes(byte[] b, int off, int len) {
        if (len != 3) return null;
        byte kind = b[off], num = b[off + 1], side = b[off + 2];
        if ((kind != 'F' && kind != 'G') || (num != '1' && num != '2') || (side != 'L' && side != 'R')) return null;
        int i = (kind == 'G' ? 4 : 0) + (side == 'R' ? 2 : 0) + (num == '2' ? 1 : 0);
        return VALUES[i];
    }
}

package phalanx.comm.perception;

/**
 * The Nao's hinge joints with their perceptor (HJ) and effector names. Angles read in degrees;
 * effectors take a velocity in rad/s (recordings README). Toes (llj7/rlj7) exist on type 4 only.
 */
public enum Joint {
    HJ1("hj1", "he1", "neck yaw"), HJ2("hj2", "he2", "neck pitch"),
    LAJ1("laj1", "lae1", "left shoulder pitch"), LAJ2("laj2", "lae2", "left shoulder yaw"),
    LAJ3("laj3", "lae3", "left arm roll"), LAJ4("laj4", "lae4", "left arm yaw"),
    RAJ1("raj1", "rae1", "right shoulder pitch"), RAJ2("raj2", "rae2", "right shoulder yaw"),
    RAJ3("raj3", "rae3", "right arm roll"), RAJ4("raj4", "rae4", "right arm yaw"),
    LLJ1("llj1", "lle1", "left hip yaw-pitch"), LLJ2("llj2", "lle2", "left hip roll"),
    LLJ3("llj3", "lle3", "left hip pitch"), LLJ4("llj4", "lle4", "left knee pitch"),
    LLJ5("llj5", "lle5", "left ankle pitch"), LLJ6("llj6", "lle6", "left ankle roll"),
    LLJ7("llj7", "lle7", "left toe pitch"),
    RLJ1("rlj1", "rle1", "right hip yaw-pitch"), RLJ2("rlj2", "rle2", "right hip roll"),
    RLJ3("rlj3", "rle3", "right hip pitch"), RLJ4("rlj4", "rle4", "right knee pitch"),
    RLJ5("rlj5", "rle5", "right ankle pitch"), RLJ6("rlj6", "rle6", "right ankle roll"),
    RLJ7("rlj7", "rle7", "right toe pitch");

    private static final Joint[] VALUES = values();
    public static final int COUNT = VALUES.length;

    private final String perceptorName;
    private final String effectorName;
    private final String description;

    Joint(String perceptorName, String effectorName, String description) {
        this.perceptorName = perceptorName;
        this.effectorName = effectorName;
        this.description = description;
    }

    public String perceptorName() { return perceptorName; }
    public String effectorName() { return effectorName; }
    public String description() { return description; }
    public boolean isToe() { return this == LLJ7 || this == RLJ7; }

    public static Joint byIndex(int i) { return VALUES[i]; }

    /** The joint with this perceptor ("hj1") or effector ("he1") name, or null. */
    public static Joint byName(String name) {
        for (Joint j : VALUES) {
            if (j.perceptorName.equals(name) || j.effectorName.equals(name)) return j;
        }
        return null;
    }

    /**
     * Decodes a perceptor name straight from message bytes without allocating: hj1-2,
     * laj1-4, raj1-4, llj1-7, rlj1-7. Returns null for anything else.
     */
    public static Joint fromPerceptorBytes(byte[] b, int off, int len) {
        if (len == 3 && b[off] == 'h' && b[off + 1] == 'j') {
            int n = b[off + 2] - '0';
            return n == 1 ? HJ1 : n == 2 ? HJ2 : null;
        }
        if (len != 4 || b[off + 2] != 'j') return null;
        char side = (char) b[off], limb = (char) b[off + 1];
        int n = b[off + 3] - '0';
        if (limb == 'a' && n >= 1 && n <= 4) {
            if (side == 'l') return VALUES[LAJ1.ordinal() + n - 1];
            if (side == 'r') return VALUES[RAJ1.ordinal() + n - 1];
        } else if (limb == 'l' && n >= 1 && n <= 7) {
            if (side == 'l') return VALUES[LLJ1.ordinal() + n - 1];
            if (side == 'r') return VALUES[RLJ1.ordinal() + n - 1];
        }
        return null;
    }
}

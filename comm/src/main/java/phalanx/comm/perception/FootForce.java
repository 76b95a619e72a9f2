package phalanx.comm.perception;

/**
 * A force resistance perceptor (FRP): lf, rf, and on type 4 the toes lf1, rf1. Present only in
 * cycles where the foot touches something. Point of contact and force, both in the foot's frame.
 */
public record FootForce(Foot foot, Vector3 contact, Vector3 force) {

    public enum Foot {
        LEFT("lf"), RIGHT("rf"), LEFT_TOE("lf1"), RIGHT_TOE("rf1");

        private final String wireName;
        Foot(String wireName) { this.wireName = wireName; }
        public String wireName() { return wireName; }

        public static Foot fromWire(String s) {
            for (Foot f : values()) if (f.wireName.equals(s)) return f;
            return null;
        }
    }
}

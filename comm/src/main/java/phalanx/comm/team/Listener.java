package phalanx.comm.team;

import phalanx.comm.perception.Hear;
import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

/**
 * The hear side shared by both state machines: skips one's own messages, drops messages the server
 * labelled with another team without checking them, checks the rest and counts rejections.
 */
public final class Listener {
    private final SayCodec codec;
    private final String team;
    private final long[] rejected = new long[Rejection.values().length];

    public Listener(SayCodec codec, String team) {
        if (codec == null) throw new IllegalArgumentException("codec is null");
        this.codec = codec;
        this.team = team;
    }

    /** Our message in this hear, or null (own, foreign or failing the check: counted). */
    public Decoded accept(Hear h, long cycle) {
        if (h == null || h.self()) return null;
        if (team != null && h.team() != null && !team.equals(h.team())) {
            rejected[Rejection.FOREIGN_TEAM.ordinal()]++;
            return null;
        }
        Decoded d = codec.decode(h.message(), cycle);
        if (!d.accepted()) {
            rejected[d.rejection().ordinal()]++;
            return null;
        }
        return d;
    }

    public long rejected(Rejection r) {
        return rejected[r.ordinal()];
    }
}

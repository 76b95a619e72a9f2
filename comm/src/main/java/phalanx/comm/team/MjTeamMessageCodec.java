package phalanx.comm.team;

import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.util.ArrayList;
import java.util.Base64;
import java.util.Collection;
import java.util.List;

/**
 * {@link TeamMessageCodec}'s messages for rcssservermj, whose say carries at most 10 bytes (base64 on
 * the wire; rcsssmj 0.2.1 drops longer ones): every {@link TeamMessage} in one frame of exactly 10 binary
 * bytes, with a keyed check that ties it to our team's per-match key and to the cycle it was said in.
 *
 * <h2>Layout</h2>
 * 80 bits, most significant bit of byte 0 first.
 * <pre>
 * bits 0-23   check: the low 24 bits of SipHash-2-4(key, [version 2][said cycle, 8 bytes LE][bytes 3-9])
 * bits 24-79  body (56 bits), zero-padded to the end of the frame:
 *   bits 0-2  type: 0 i, 1 s, 2 C, 3 L, 4 B, 5 X, 6 e, 7 a
 *   bits 3-4  said cycle mod 4 (the listener knows it to within the latency window, 2-3 cycles)
 *   then, by type (u = uniform number 4 bits; X = x 10 bits at 6 cm: (q - 512) x 0.06 m, ±30.72 m;
 *   Y = y 9 bits at 8 cm: (q - 256) x 0.08 m, ±20.48 m (the field is 55 x 36 m, MjField.SSIM);
 *   A = angle 8 bits at 360/256 = 1.41°; D = distance 11 bits at 4 cm, 0-81.88 m):
 *   i, s, e   u                                       (9 bits)
 *   C         u, x X, y Y, θ A, ball x X, ball y Y    (55 bits)
 *   L         u, x X, y Y, θ A                        (36 bits)
 *   B         u, ball distance D, ball angle A        (28 bits)
 *   X         u, fallen 1 bit                         (10 bits)
 *   a         remaining 4 bits (0-15), then entries until the rest of the frame is zero (an entry never
 *             starts with 8 zero bits: recipients are 1-15):
 *             recipient u, action id 4 bits, then by ActionId.Params: nothing (8 bits in all),
 *             direction A (16), or x X, y Y, θ A (35); 47 bits hold one pose and one bare action,
 *             three directions or five bare actions.
 * </pre>
 * <b>Reduced, not split, reports:</b> every report fits one frame, at a coarser grid than SimSpark's
 * (6 and 8 cm against 4 cm; angles unchanged), because a player has one report slot a round: a report in
 * two frames would take two slots and be lost when either half is. <b>Split dispatches:</b> one frame holds
 * one Walk to Coordinate (two fit in SimSpark's 20 characters), so {@link #pack} spreads a dispatch over
 * up to 16 frames (4 remaining bits, where SimSpark has 3): 6 field players of 7 v 7 with a pose each
 * take 6 frames, 10 of 11 v 11 take 10. Target poses keep their full grid, since a player walks to them.
 *
 * <p>The check makes a forged message pass with probability 2^-24 (6 x 10^-8). rcsssmj labels no message
 * with a team, so the check is also all that tells an opponent's message from ours: one in our layout on
 * our clock passes with the same 2^-24 (7 opponents saying a forged Complete every cycle to our 6
 * listeners for 10 minutes of play: at most 7 x 30 000 x 6 x 2^-24 = 0.08 accepted); random bytes must
 * also fit the said-cycle bits (1/2) and the zero padding (a Complete leaves 1 bit, the other types more),
 * of the order of 2^-29. Binding the check to the said cycle rejects a replay: measured on rcsssmj 0.2.1,
 * a say sent in reply to perception c is heard in perception c + 2 (docs/rcssservermj.md), so a replay
 * arrives 4 cycles late at the earliest while we accept at most 3. Cycles are counted on the server's
 * clock by both sides, see {@link #cycleOf}.
 *
 * <p>Not thread-safe: each player owns one codec.
 */
public final class MjTeamMessageCodec {
    /** rcsssmj 0.2.1 delivers a heard message only if it has at most this many bytes (MjActions.MAX_SAY_BYTES). */
    static final int FRAME_BYTES = 10;
    static final int CHECK_BITS = 24;
    static final int CHECK_BYTES = CHECK_BITS / 8;
    static final int BODY_BITS = 8 * FRAME_BYTES - CHECK_BITS;
    static final int HEADER_BITS = 5;
    static final int REMAINING_BITS = 4;
    static final int ACTION_ENTRY_BITS = BODY_BITS - HEADER_BITS - REMAINING_BITS;
    static final int MAX_ACTION_MESSAGES = 1 << REMAINING_BITS;
    static final int X_BITS = 10, Y_BITS = 9;
    static final double X_STEP = 0.06, Y_STEP = 0.08;
    static final int ANGLE_BITS = 8;
    static final double ANGLE_STEP = 360.0 / (1 << ANGLE_BITS);
    static final int DIST_BITS = 11;
    static final double DIST_STEP = 0.04;
    private static final byte VERSION = 2;

    static final int INIT = 0, START = 1, COMPLETE = 2, LOCATION = 3, BALL = 4, UNAWARE = 5, END = 6, ACTIONS = 7;

    private final TeamKey key;
    private final int minLatency, maxLatency;
    private final byte[] macInput = new byte[1 + 8 + FRAME_BYTES - CHECK_BYTES];
    private byte[] w;
    private int wBit;
    private byte[] r;
    private int rBit;

    public MjTeamMessageCodec(TeamKey key, ChannelConfig config) {
        if (key == null) throw new IllegalArgumentException("team key is null");
        this.key = key;
        this.minLatency = config.minLatencyCycles();
        this.maxLatency = config.maxLatencyCycles();
    }

    /**
     * The cycle number of a perception's {@code (time (now T))}: T in whole hundredths, halved. rcsssmj steps
     * 0.02 s and may start at an odd hundredth (138.83, 138.85, ...), where {@code Math.round(T / 0.02)} would
     * sit on .5 and round either way; this gives consecutive perceptions consecutive numbers.
     */
    public static long cycleOf(double serverTime) {
        return Math.floorDiv(Math.round(serverTime * 100), 2);
    }

    // ---- encoding ------------------------------------------------------------------------------

    /**
     * The 10-byte frame for this message, said in the reply to the perception of {@code saidCycle}
     * (pass it to {@code MjActions.say}). Refuses (IllegalArgumentException) what cannot be sent: bad
     * uniform numbers, non-finite values, action lists that do not fit one frame.
     */
    public byte[] encode(TeamMessage message, long saidCycle) {
        w = new byte[FRAME_BYTES];
        wBit = CHECK_BITS;
        int cycleBits = (int) (saidCycle & 3);
        if (message instanceof TeamMessage.Init m) {
            header(INIT, cycleBits);
            unum(m.sender());
        } else if (message instanceof TeamMessage.Start m) {
            header(START, cycleBits);
            unum(m.sender());
        } else if (message instanceof TeamMessage.End m) {
            header(END, cycleBits);
            unum(m.sender());
        } else if (message instanceof TeamMessage.Complete m) {
            header(COMPLETE, cycleBits);
            unum(m.sender());
            x(m.x(), "x");
            y(m.y(), "y");
            angle(m.thetaDeg(), "orientation");
            x(m.ballX(), "ball x");
            y(m.ballY(), "ball y");
        } else if (message instanceof TeamMessage.Location m) {
            header(LOCATION, cycleBits);
            unum(m.sender());
            x(m.x(), "x");
            y(m.y(), "y");
            angle(m.thetaDeg(), "orientation");
        } else if (message instanceof TeamMessage.Ball m) {
            if (!Double.isFinite(m.distance()) || m.distance() < 0) {
                throw new IllegalArgumentException("ball distance must be finite and not negative, got " + m.distance());
            }
            header(BALL, cycleBits);
            unum(m.sender());
            put((int) Math.min(Math.round(m.distance() / DIST_STEP), (1 << DIST_BITS) - 1), DIST_BITS);
            angle(m.angleDeg(), "ball angle");
        } else if (message instanceof TeamMessage.Unaware m) {
            header(UNAWARE, cycleBits);
            unum(m.sender());
            put(m.fallen() ? 1 : 0, 1);
        } else if (message instanceof TeamMessage.Actions m) {
            if (m.remaining() < 0 || m.remaining() >= MAX_ACTION_MESSAGES) {
                throw new IllegalArgumentException("remaining must be 0-" + (MAX_ACTION_MESSAGES - 1) + ", got " + m.remaining());
            }
            if (m.actions().isEmpty()) throw new IllegalArgumentException("an action message needs at least one action");
            int bits = 0;
            for (Action a : m.actions()) bits += entryBits(a.id());
            if (bits > ACTION_ENTRY_BITS) {
                throw new IllegalArgumentException(m.actions().size() + " actions need " + bits + " bits, one frame holds "
                        + ACTION_ENTRY_BITS + "; use MjTeamMessageCodec.pack");
            }
            header(ACTIONS, cycleBits);
            put(m.remaining(), REMAINING_BITS);
            for (Action a : m.actions()) {
                unum(a.recipient());
                put(a.id().code(), 4);
                switch (a.id().params()) {
                    case NONE -> { }
                    case DIRECTION -> angle(a.thetaDeg(), "direction");
                    case POSE -> {
                        x(a.x(), "target x");
                        y(a.y(), "target y");
                        angle(a.thetaDeg(), "target orientation");
                    }
                }
            }
        } else {
            throw new IllegalArgumentException("message is null");
        }
        int check = check(saidCycle, w);
        w[0] = (byte) (check >>> 16);
        w[1] = (byte) (check >>> 8);
        w[2] = (byte) check;
        byte[] out = w;
        w = null;
        return out;
    }

    /** Bits one action takes in an "a" frame. */
    static int entryBits(ActionId id) {
        return 8 + switch (id.params()) {
            case NONE -> 0;
            case DIRECTION -> ANGLE_BITS;
            case POSE -> X_BITS + Y_BITS + ANGLE_BITS;
        };
    }

    /**
     * Packs one dispatch into as few "a" frames as fit (first fit, largest actions first), each telling
     * how many follow. Refuses two actions for one recipient and more than 16 frames.
     */
    public static List<TeamMessage.Actions> pack(Collection<Action> actions) {
        return ActionPacking.pack(actions, MjTeamMessageCodec::entryBits, ACTION_ENTRY_BITS, MAX_ACTION_MESSAGES, "frames");
    }

    /**
     * This codec as the round state machines take it ({@link SayCodec}): each frame as the standard padded base64
     * text that {@code (SPK say 100 <base64>)} carries and {@code (MIC hear (AZ <base64>))} delivers (16 characters),
     * so {@code CoordinatorRounds} and {@code FieldPlayerRounds} run unchanged on rcssservermj. A heard text that is
     * not base64 is rejected as {@link Rejection#FOREIGN_CHARACTER}.
     */
    public SayCodec text() {
        return new SayCodec() {
            @Override public String encode(TeamMessage message, long saidCycle) {
                return Base64.getEncoder().encodeToString(MjTeamMessageCodec.this.encode(message, saidCycle));
            }

            @Override public Decoded decode(String text, long heardCycle) {
                if (text == null || text.isEmpty()) return TeamMessageCodec.rejected(Rejection.EMPTY);
                byte[] bytes;
                try {
                    bytes = Base64.getDecoder().decode(text);
                } catch (IllegalArgumentException e) {
                    return TeamMessageCodec.rejected(Rejection.FOREIGN_CHARACTER);
                }
                return MjTeamMessageCodec.this.decode(bytes, heardCycle);
            }

            @Override public List<TeamMessage.Actions> packActions(Collection<Action> actions) {
                return pack(actions);
            }
        };
    }

    private void header(int type, int cycleBits) {
        put(type, 3);
        put(cycleBits, 2);
    }

    private void unum(int u) {
        if (u < 1 || u > 15) throw new IllegalArgumentException("uniform number must be 1-15, got " + u);
        put(u, 4);
    }

    private void x(double v, String what) {
        grid(v, X_STEP, X_BITS, what);
    }

    private void y(double v, String what) {
        grid(v, Y_STEP, Y_BITS, what);
    }

    /** Clamped to the covered range. */
    private void grid(double v, double step, int bits, String what) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException(what + " must be finite, got " + v);
        long q = Math.round(v / step) + (1L << (bits - 1));
        put((int) Math.max(0, Math.min((1L << bits) - 1, q)), bits);
    }

    private void angle(double deg, String what) {
        if (!Double.isFinite(deg)) throw new IllegalArgumentException(what + " must be finite, got " + deg);
        put((int) Math.floorMod(Math.round(deg / ANGLE_STEP), 1L << ANGLE_BITS), ANGLE_BITS);
    }

    private void put(int value, int bits) {
        for (int i = bits - 1; i >= 0; i--, wBit++) {
            if (((value >>> i) & 1) != 0) w[wBit >>> 3] |= (byte) (0x80 >>> (wBit & 7));
        }
    }

    // ---- decoding ------------------------------------------------------------------------------

    /**
     * Our message in these heard bytes (MjPerception.Heard's, base64 already decoded) heard in the
     * perception of {@code heardCycle}, or why they are not one. Never throws, whatever the bytes.
     */
    public Decoded decode(byte[] bytes, long heardCycle) {
        if (bytes == null || bytes.length == 0) return TeamMessageCodec.rejected(Rejection.EMPTY);
        if (bytes.length > FRAME_BYTES) return TeamMessageCodec.rejected(Rejection.TOO_LONG);
        if (bytes.length < FRAME_BYTES) return TeamMessageCodec.rejected(Rejection.TOO_SHORT);
        r = bytes;
        rBit = CHECK_BITS;
        try {
            int type = get(3);
            int cycleBits = get(2);
            long said = Long.MIN_VALUE;
            for (int lat = minLatency; lat <= maxLatency; lat++) {
                if (((heardCycle - lat) & 3) == cycleBits) said = heardCycle - lat;
            }
            if (said == Long.MIN_VALUE) return TeamMessageCodec.rejected(Rejection.WRONG_TIME);
            int check = (bytes[0] & 0xff) << 16 | (bytes[1] & 0xff) << 8 | (bytes[2] & 0xff);
            if (check != check(said, bytes)) return TeamMessageCodec.rejected(Rejection.BAD_CHECK);
            TeamMessage m = body(type);
            if (m == null) return TeamMessageCodec.rejected(Rejection.MALFORMED);
            return new Decoded(m, said, null);
        } finally {
            r = null;
        }
    }

    /** The body after the header, or null if it is not canonical (values, padding not all zero). */
    private TeamMessage body(int type) {
        TeamMessage m;
        switch (type) {
            case INIT, START, END -> {
                int u = get(4);
                if (u == 0) return null;
                m = type == INIT ? new TeamMessage.Init(u) : type == START ? new TeamMessage.Start(u) : new TeamMessage.End(u);
            }
            case COMPLETE -> {
                int u = get(4);
                if (u == 0) return null;
                double x = gx(), y = gy(), th = ang(), bx = gx(), by = gy();
                m = new TeamMessage.Complete(u, x, y, th, bx, by);
            }
            case LOCATION -> {
                int u = get(4);
                if (u == 0) return null;
                double x = gx(), y = gy(), th = ang();
                m = new TeamMessage.Location(u, x, y, th);
            }
            case BALL -> {
                int u = get(4);
                if (u == 0) return null;
                double d = get(DIST_BITS) * DIST_STEP;
                m = new TeamMessage.Ball(u, d, ang());
            }
            case UNAWARE -> {
                int u = get(4);
                if (u == 0) return null;
                m = new TeamMessage.Unaware(u, get(1) == 1);
            }
            default -> { // ACTIONS: the 3 type bits have no free value
                int rem = get(REMAINING_BITS);
                List<Action> actions = new ArrayList<>(2);
                // entries until fewer than 8 bits are left, or an all-zero recipient and id (the padding)
                while (remaining() >= 8 && peek(8) != 0) {
                    int rc = get(4);
                    ActionId id = ActionId.ofCode(get(4));
                    if (rc == 0 || id == null) return null;
                    switch (id.params()) {
                        case NONE -> actions.add(new Action(rc, id, 0, 0, 0));
                        case DIRECTION -> {
                            if (remaining() < ANGLE_BITS) return null;
                            actions.add(new Action(rc, id, 0, 0, ang()));
                        }
                        case POSE -> {
                            if (remaining() < X_BITS + Y_BITS + ANGLE_BITS) return null;
                            double x = gx(), y = gy();
                            actions.add(new Action(rc, id, x, y, ang()));
                        }
                    }
                }
                if (actions.isEmpty()) return null;
                m = new TeamMessage.Actions(rem, actions);
            }
        }
        // canonical: the rest of the frame is zero
        while (remaining() > 0) {
            if (get(Math.min(remaining(), 8)) != 0) return null;
        }
        return m;
    }

    private double gx() {
        return (get(X_BITS) - (1 << (X_BITS - 1))) * X_STEP;
    }

    private double gy() {
        return (get(Y_BITS) - (1 << (Y_BITS - 1))) * Y_STEP;
    }

    private double ang() {
        double a = get(ANGLE_BITS) * ANGLE_STEP;
        return a >= 180 ? a - 360 : a;
    }

    private int remaining() {
        return 8 * FRAME_BYTES - rBit;
    }

    private int peek(int bits) {
        int at = rBit;
        int v = get(bits);
        rBit = at;
        return v;
    }

    private int get(int bits) {
        int v = 0;
        for (int i = 0; i < bits; i++, rBit++) v = (v << 1) | ((r[rBit >>> 3] >>> (7 - (rBit & 7))) & 1);
        return v;
    }

    private int check(long saidCycle, byte[] frame) {
        byte[] in = macInput;
        in[0] = VERSION;
        for (int i = 0; i < 8; i++) in[1 + i] = (byte) (saidCycle >>> (8 * i));
        System.arraycopy(frame, CHECK_BYTES, in, 9, FRAME_BYTES - CHECK_BYTES);
        return (int) (SipHash.hash(key.k0, key.k1, in, in.length) & ((1L << CHECK_BITS) - 1));
    }
}

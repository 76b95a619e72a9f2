package phalanx.comm.team;

import phalanx.comm.effector.EffectorMessage;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * Turns {@link TeamMessage}s into say text of at most 20 characters and back, with a check that ties
 * each message to our team's per-match key and to the cycle it was said in.
 *
 * <h2>Layout</h2>
 * Every character carries 6 bits, from the 64 characters {@code A-Z a-z 0-9 - _} (all legal in a say,
 * none of the ones reported to break messages: no quote, backslash, semicolon, space or parenthesis).
 * Bits are read most significant first.
 * <pre>
 * chars 0-4   check: the low 30 bits of SipHash-2-4(key, [version 1][said cycle, 8 bytes LE][chars 5..end])
 * chars 5-    body, zero-padded to whole characters:
 *   bits 0-3  type: 0 i, 1 s, 2 C, 3 L, 4 B, 5 X, 6 e, 7 a (8-15 free)
 *   bits 4-5  said cycle mod 4 (the listener knows it to within the latency window, 2-3 cycles)
 *   then, by type (u = uniform number 4 bits, P = position 10 bits at 4 cm: (q - 512) x 0.04 m,
 *   covering ±20.48 m; A = angle 8 bits at 360/256 = 1.41°; D = distance 10 bits at 4 cm, 0-40.92 m):
 *   i, s, e   u                       (7 characters)
 *   C         u, x P, y P, θ A, ball x P, ball y P   (15 characters)
 *   L         u, x P, y P, θ A                       (12 characters)
 *   B         u, ball distance D, ball angle A       (10 characters)
 *   X         u, fallen 1 bit                        (7 characters)
 *   a         remaining 3 bits, then entries until the bits run out:
 *             recipient u, action id 4 bits, then by ActionId.Params: nothing (8 bits in all),
 *             direction A (16), or x P, y P, θ A (36): two poses and one bare action fit in 20 characters.
 * </pre>
 * Positions outside the covered range are clamped to it (the field is 30 x 20 m). The check makes a
 * forged message pass with probability 2^-30; binding it to the said cycle rejects a replay, which
 * reaches us at least 2 x 2 cycles after the original was said while we accept at most 3.
 *
 * <p>Not thread-safe: each player owns one codec (it reuses its buffers, so decoding allocates only the
 * message it accepts).
 */
public final class TeamMessageCodec implements SayCodec {
    static final String ALPHABET = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    static final int MAX_LENGTH = EffectorMessage.MAX_SAY_LENGTH;
    static final int CHECK_CHARS = 5;
    static final int CHECK_BITS = 6 * CHECK_CHARS;
    static final int MAX_BODY_BITS = 6 * (MAX_LENGTH - CHECK_CHARS);
    static final int HEADER_BITS = 6;
    static final int REMAINING_BITS = 3;
    /** Bits left for action entries in one "a" message. */
    static final int ACTION_ENTRY_BITS = MAX_BODY_BITS - HEADER_BITS - REMAINING_BITS;
    static final int MAX_ACTION_MESSAGES = 1 << REMAINING_BITS;
    static final double POS_STEP = 0.04;
    static final int POS_BITS = 10;
    static final int POS_OFFSET = 1 << (POS_BITS - 1);
    static final int ANGLE_BITS = 8;
    static final double ANGLE_STEP = 360.0 / (1 << ANGLE_BITS);
    static final double DIST_STEP = 0.04;
    static final int DIST_BITS = 10;
    private static final byte VERSION = 1;

    static final int INIT = 0, START = 1, COMPLETE = 2, LOCATION = 3, BALL = 4, UNAWARE = 5, END = 6, ACTIONS = 7;

    private static final int[] SYMBOL = new int[128];

    static {
        java.util.Arrays.fill(SYMBOL, -1);
        for (int i = 0; i < ALPHABET.length(); i++) SYMBOL[ALPHABET.charAt(i)] = i;
    }

    /** Why a heard text is not one of our messages (for counters and logs; never thrown). */
    public enum Rejection {
        /** Labelled with another team's name by the server: an opponent's message, not even checked. */
        FOREIGN_TEAM,
        EMPTY,
        TOO_LONG,
        TOO_SHORT,
        /** A character our alphabet never uses. */
        FOREIGN_CHARACTER,
        /** The said-cycle bits do not fit the time it was heard: stale or replayed. */
        WRONG_TIME,
        /** The check does not match: foreign, corrupted, spoofed or replayed. */
        BAD_CHECK,
        /** The check matches but the body does not parse: a player with another protocol version. */
        MALFORMED
    }

    /** A decoded message with the cycle it was said in, or the reason it was rejected. */
    public record Decoded(TeamMessage message, long saidCycle, Rejection rejection) {
        public boolean accepted() {
            return rejection == null;
        }
    }

    private static final Decoded[] REJECTED = new Decoded[Rejection.values().length];

    static {
        for (Rejection r : Rejection.values()) REJECTED[r.ordinal()] = new Decoded(null, -1, r);
    }

    static Decoded rejected(Rejection r) {
        return REJECTED[r.ordinal()];
    }

    private final TeamKey key;
    private final int minLatency, maxLatency;
    private final char[] out = new char[MAX_LENGTH];
    private final byte[] macInput = new byte[1 + 8 + MAX_LENGTH];
    private final int[] symbols = new int[MAX_LENGTH];
    // bit writer / reader state
    private int wPos, wCur, wBits;
    private int rBit, rEnd;

    public TeamMessageCodec(TeamKey key, ChannelConfig config) {
        if (key == null) throw new IllegalArgumentException("team key is null");
        this.key = key;
        this.minLatency = config.minLatencyCycles();
        this.maxLatency = config.maxLatencyCycles();
    }

    // ---- encoding ------------------------------------------------------------------------------

    /**
     * The say text for this message, said in the reply to the perception of {@code saidCycle}.
     * Refuses (IllegalArgumentException) what cannot be sent: bad uniform numbers, non-finite
     * values, action lists that do not fit.
     */
    @Override public String encode(TeamMessage message, long saidCycle) {
        wPos = CHECK_CHARS;
        wCur = 0;
        wBits = 0;
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
            position(m.x(), "x");
            position(m.y(), "y");
            angle(m.thetaDeg(), "orientation");
            position(m.ballX(), "ball x");
            position(m.ballY(), "ball y");
        } else if (message instanceof TeamMessage.Location m) {
            header(LOCATION, cycleBits);
            unum(m.sender());
            position(m.x(), "x");
            position(m.y(), "y");
            angle(m.thetaDeg(), "orientation");
        } else if (message instanceof TeamMessage.Ball m) {
            if (!Double.isFinite(m.distance()) || m.distance() < 0) {
                throw new IllegalArgumentException("ball distance must be finite and not negative, got " + m.distance());
            }
            header(BALL, cycleBits);
            unum(m.sender());
            put(Math.min((int) Math.round(m.distance() / DIST_STEP), (1 << DIST_BITS) - 1), DIST_BITS);
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
                throw new IllegalArgumentException(m.actions().size() + " actions need " + bits + " bits, one message holds "
                        + ACTION_ENTRY_BITS + "; use TeamMessageCodec.pack");
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
                        position(a.x(), "target x");
                        position(a.y(), "target y");
                        angle(a.thetaDeg(), "target orientation");
                    }
                }
            }
        } else {
            throw new IllegalArgumentException("message is null");
        }
        if (wBits > 0) {
            put(0, 6 - wBits);
        }
        int check = check(saidCycle, out, CHECK_CHARS, wPos);
        for (int i = CHECK_CHARS - 1; i >= 0; i--) {
            out[i] = ALPHABET.charAt(check & 63);
            check >>>= 6;
        }
        String text = new String(out, 0, wPos);
        String problem = EffectorMessage.sayProblem(text);
        if (problem != null) throw new IllegalStateException("codec produced an unsayable message: " + problem);
        return text;
    }

    /** Bits one action takes in an "a" message. */
    static int entryBits(ActionId id) {
        return 8 + switch (id.params()) {
            case NONE -> 0;
            case DIRECTION -> ANGLE_BITS;
            case POSE -> 2 * POS_BITS + ANGLE_BITS;
        };
    }

    /**
     * Packs one dispatch into as few "a" messages as fit (first fit, largest actions first), each
     * telling how many follow. Refuses two actions for one recipient and more than 8 messages.
     */
    public static List<TeamMessage.Actions> pack(Collection<Action> actions) {
        return ActionPacking.pack(actions, TeamMessageCodec::entryBits, ACTION_ENTRY_BITS, MAX_ACTION_MESSAGES, "messages");
    }

    @Override public List<TeamMessage.Actions> packActions(Collection<Action> actions) {
        return pack(actions);
    }

    private void header(int type, int cycleBits) {
        put(type, 4);
        put(cycleBits, 2);
    }

    private void unum(int u) {
        if (u < 1 || u > 15) throw new IllegalArgumentException("uniform number must be 1-15, got " + u);
        put(u, 4);
    }

    private void position(double v, String what) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException(what + " must be finite, got " + v);
        long q = Math.round(v / POS_STEP) + POS_OFFSET;
        put((int) Math.max(0, Math.min((1 << POS_BITS) - 1, q)), POS_BITS);
    }

    private void angle(double deg, String what) {
        if (!Double.isFinite(deg)) throw new IllegalArgumentException(what + " must be finite, got " + deg);
        put((int) Math.floorMod(Math.round(deg / ANGLE_STEP), 1L << ANGLE_BITS), ANGLE_BITS);
    }

    private void put(int value, int bits) {
        for (int i = bits - 1; i >= 0; i--) {
            wCur = (wCur << 1) | ((value >>> i) & 1);
            if (++wBits == 6) {
                if (wPos == MAX_LENGTH) throw new IllegalArgumentException("message does not fit in " + MAX_LENGTH + " characters");
                out[wPos++] = ALPHABET.charAt(wCur);
                wCur = 0;
                wBits = 0;
            }
        }
    }

    // ---- decoding ------------------------------------------------------------------------------

    /**
     * Our message in this text heard in the perception of {@code heardCycle}, or why it is not one.
     * Never throws, whatever the text.
     */
    @Override public Decoded decode(String text, long heardCycle) {
        if (text == null || text.isEmpty()) return rejected(Rejection.EMPTY);
        int len = text.length();
        if (len > MAX_LENGTH) return rejected(Rejection.TOO_LONG);
        if (len < CHECK_CHARS + 2) return rejected(Rejection.TOO_SHORT);
        for (int i = 0; i < len; i++) {
            char c = text.charAt(i);
            int s = c < 128 ? SYMBOL[c] : -1;
            if (s < 0) return rejected(Rejection.FOREIGN_CHARACTER);
            symbols[i] = s;
        }
        rBit = 6 * CHECK_CHARS;
        rEnd = 6 * len;
        int type = get(4);
        int cycleBits = get(2);
        long said = Long.MIN_VALUE;
        for (int lat = minLatency; lat <= maxLatency; lat++) {
            if (((heardCycle - lat) & 3) == cycleBits) said = heardCycle - lat;
        }
        if (said == Long.MIN_VALUE) return rejected(Rejection.WRONG_TIME);
        int check = 0;
        for (int i = 0; i < CHECK_CHARS; i++) check = (check << 6) | symbols[i];
        for (int i = CHECK_CHARS; i < len; i++) out[i] = text.charAt(i);
        if (check != check(said, out, CHECK_CHARS, len)) return rejected(Rejection.BAD_CHECK);
        TeamMessage m = body(type);
        if (m == null) return rejected(Rejection.MALFORMED);
        return new Decoded(m, said, null);
    }

    /** The body after the header, or null if it is not canonical (wrong length, padding, values). */
    private TeamMessage body(int type) {
        TeamMessage m;
        switch (type) {
            case INIT, START, END -> {
                if (remaining() < 4) return null;
                int u = get(4);
                if (u == 0) return null;
                m = type == INIT ? new TeamMessage.Init(u) : type == START ? new TeamMessage.Start(u) : new TeamMessage.End(u);
            }
            case COMPLETE -> {
                if (remaining() < 4 + 4 * POS_BITS + ANGLE_BITS) return null;
                int u = get(4);
                if (u == 0) return null;
                double x = pos(), y = pos(), th = ang(), bx = pos(), by = pos();
                m = new TeamMessage.Complete(u, x, y, th, bx, by);
            }
            case LOCATION -> {
                if (remaining() < 4 + 2 * POS_BITS + ANGLE_BITS) return null;
                int u = get(4);
                if (u == 0) return null;
                double x = pos(), y = pos(), th = ang();
                m = new TeamMessage.Location(u, x, y, th);
            }
            case BALL -> {
                if (remaining() < 4 + DIST_BITS + ANGLE_BITS) return null;
                int u = get(4);
                if (u == 0) return null;
                double d = get(DIST_BITS) * DIST_STEP;
                m = new TeamMessage.Ball(u, d, ang());
            }
            case UNAWARE -> {
                if (remaining() < 5) return null;
                int u = get(4);
                if (u == 0) return null;
                m = new TeamMessage.Unaware(u, get(1) == 1);
            }
            case ACTIONS -> {
                if (remaining() < REMAINING_BITS + 8) return null;
                int rem = get(REMAINING_BITS);
                List<Action> actions = new ArrayList<>(3);
                while (remaining() >= 8) {
                    int r = get(4);
                    ActionId id = ActionId.ofCode(get(4));
                    if (r == 0 || id == null) return null;
                    switch (id.params()) {
                        case NONE -> actions.add(new Action(r, id, 0, 0, 0));
                        case DIRECTION -> {
                            if (remaining() < ANGLE_BITS) return null;
                            actions.add(new Action(r, id, 0, 0, ang()));
                        }
                        case POSE -> {
                            if (remaining() < 2 * POS_BITS + ANGLE_BITS) return null;
                            double x = pos(), y = pos();
                            actions.add(new Action(r, id, x, y, ang()));
                        }
                    }
                }
                m = new TeamMessage.Actions(rem, actions);
            }
            default -> {
                return null;
            }
        }
        // canonical: fewer than 6 padding bits, all zero
        int pad = remaining();
        if (pad >= 6 || (pad > 0 && get(pad) != 0)) return null;
        return m;
    }

    private double pos() {
        return (get(POS_BITS) - POS_OFFSET) * POS_STEP;
    }

    private double ang() {
        double a = get(ANGLE_BITS) * ANGLE_STEP;
        return a >= 180 ? a - 360 : a;
    }

    private int remaining() {
        return rEnd - rBit;
    }

    private int get(int bits) {
        int v = 0;
        for (int i = 0; i < bits; i++, rBit++) {
            v = (v << 1) | ((symbols[rBit / 6] >>> (5 - rBit % 6)) & 1);
        }
        return v;
    }

    private int check(long saidCycle, char[] text, int from, int to) {
        byte[] in = macInput;
        in[0] = VERSION;
        for (int i = 0; i < 8; i++) in[1 + i] = (byte) (saidCycle >>> (8 * i));
        int n = 9;
        for (int i = from; i < to; i++) in[n++] = (byte) text[i];
        return (int) (SipHash.hash(key.k0, key.k1, in, n) & ((1L << CHECK_BITS) - 1));
    }
}

package phalanx.comm.sexp;

import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.FootForce;
import phalanx.comm.perception.GameState;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.SeenLine;
import phalanx.comm.perception.SeenPlayer;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.comm.perception.Vision;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Logger;

/**
 * Parses one perceptor message (the payload of one frame) into a {@link Perception}.
 *
 * <p>It reads the bytes directly, with no tokenizer and no intermediate tree: it runs 50 times a
 * second in each of eleven JVMs sharing two cores, so the only objects it creates are the parts of
 * the perception it returns. Not thread-safe; use one parser per connection.
 *
 * <p>Every defect in the input ends in {@link MalformedMessageException}; nothing else escapes.
 * Perceptors and See items it does not know are skipped, kept raw in {@link Perception#unknown()}
 * (top level only) and logged once per name.
 */
public final class PerceptionParser {
    private static final Logger LOG = Logger.getLogger(PerceptionParser.class.getName());
    private static final Set<String> LOGGED = ConcurrentHashMap.newKeySet();
    private static final double[] POW10 = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
            1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};

    private static final PlayMode[] PLAY_MODES = PlayMode.values();

    private byte[] b;
    private int pos;
    private int end;
    // The last atom read: b[tokStart, tokStart + tokLen).
    private int tokStart;
    private int tokLen;
    // Team names repeat every message: keep the Strings instead of allocating new ones.
    private final byte[][] teamBytes = new byte[4][];
    private final String[] teamNames = new String[4];
    private final int[] hearStarts = new int[5];
    private final int[] hearLens = new int[5];

    public Perception parse(String message) throws MalformedMessageException {
        byte[] bytes = message.getBytes(StandardCharsets.ISO_8859_1);
        return parse(bytes, 0, bytes.length);
    }

    /** Parses {@code bytes[offset, offset + length)}. */
    public Perception parse(byte[] bytes, int offset, int length) throws MalformedMessageException {
        if (offset < 0 || length < 0 || offset + length > bytes.length) {
            throw new MalformedMessageException("bad buffer range", 0);
        }
        b = bytes;
        pos = offset;
        end = offset + length;
        double time = Double.NaN;
        GameState gs = null;
        Vector3 gyr = null, acc = null;
        double[] joints = null;
        List<FootForce> frp = List.of();
        Vision vision = null;
        List<Hear> hears = List.of();
        List<String> unknown = List.of();

        skipWs();
        if (pos >= end) throw new MalformedMessageException("empty message", pos);
        while (pos < end) {
            int exprStart = pos;
            open();
            atom();
            if (is("time")) {
                time = parseTime();
            } else if (is("GS")) {
                gs = parseGameState();
            } else if (is("GYR")) {
                gyr = parseNamedVector("rt");
            } else if (is("ACC")) {
                acc = parseNamedVector("a");
            } else if (is("HJ")) {
                if (joints == null) {
                    joints = new double[Joint.COUNT];
                    Arrays.fill(joints, Double.NaN);
                }
                parseJoint(joints);
            } else if (is("FRP")) {
                if (frp.isEmpty()) frp = new ArrayList<>(4);
                FootForce f = parseFootForce();
                if (f != null) frp.add(f);
            } else if (is("See")) {
                vision = parseSee();
            } else if (is("hear")) {
                if (hears.isEmpty()) hears = new ArrayList<>(2);
                hears.add(parseHear());
            } else {
                String name = tokenString();
                skipRest();
                if (unknown.isEmpty()) unknown = new ArrayList<>(2);
                unknown.add(new String(b, exprStart, pos - exprStart, StandardCharsets.ISO_8859_1));
                logOnce("perceptor " + name, "unknown perceptor '" + name + "' kept raw");
            }
            skipWs();
        }
        return new Perception(time, gs, gyr, acc, joints == null ? JointAngles.none() : new JointAngles(joints),
                frp, vision, hears, unknown);
    }

    // ---- perceptors -------------------------------------------------------------------------

    private double parseTime() throws MalformedMessageException {
        double t = Double.NaN;
        while (peekOpen()) {
            open();
            atom();
            if (is("now")) t = number(); else skipRestAfterAtom();
            close();
        }
        close();
        return t;
    }

    private GameState parseGameState() throws MalformedMessageException {
        double t = Double.NaN;
        PlayMode pm = PlayMode.UNKNOWN;
        String pmName = null;
        int unum = 0, sl = -1, sr = -1;
        Side side = null;
        while (peekOpen()) {
            open();
            atom();
            if (is("t")) {
                t = number();
            } else if (is("pm")) {
                atom();
                pmName = playModeName();
                pm = PlayMode.fromWire(pmName);
                if (pm == PlayMode.UNKNOWN) logOnce("pm " + pmName, "unknown play mode '" + pmName + "'");
            } else if (is("unum")) {
                unum = integer();
            } else if (is("team")) {
                atom();
                if (is("left")) side = Side.LEFT;
                else if (is("right")) side = Side.RIGHT;
                else throw new MalformedMessageException("team side must be left or right", tokStart);
            } else if (is("sl")) {
                sl = integer();
            } else if (is("sr")) {
                sr = integer();
            } else {
                skipRestAfterAtom();
            }
            close();
        }
        close();
        return new GameState(t, pm, pmName, unum, side, sl, sr);
    }

    private String playModeName() {
        for (PlayMode m : PLAY_MODES) {
            if (m != PlayMode.UNKNOWN && is(m.wireName())) return m.wireName(); // no allocation
        }
        return tokenString();
    }

    /** (GYR (n torso) (rt x y z)) or (ACC (n torso) (a x y z)). */
    private Vector3 parseNamedVector(String key) throws MalformedMessageException {
        Vector3 v = null;
        while (peekOpen()) {
            open();
            atom();
            if (is(key)) v = vector(); else skipRestAfterAtom();
            close();
        }
        close();
        if (v == null) throw new MalformedMessageException("missing (" + key + " x y z)", pos);
        return v;
    }

    /** (HJ (n hj1) (ax -0.00)). */
    private void parseJoint(double[] joints) throws MalformedMessageException {
        Joint joint = null;
        boolean named = false;
        double ax = Double.NaN;
        boolean hasAx = false;
        while (peekOpen()) {
            open();
            atom();
            if (is("n")) {
                atom();
                named = true;
                joint = Joint.fromPerceptorBytes(b, tokStart, tokLen);
                if (joint == null) logOnce("joint " + tokenString(), "unknown joint '" + tokenString() + "' ignored");
            } else if (is("ax")) {
                ax = number();
                hasAx = true;
            } else {
                skipRestAfterAtom();
            }
            close();
        }
        close();
        if (!named || !hasAx) throw new MalformedMessageException("HJ needs (n name) and (ax angle)", pos);
        if (joint != null) joints[joint.ordinal()] = ax;
    }

    /** (FRP (n lf) (c px py pz) (f fx fy fz)). */
    private FootForce parseFootForce() throws MalformedMessageException {
        FootForce.Foot foot = null;
        String name = null;
        Vector3 c = null, f = null;
        while (peekOpen()) {
            open();
            atom();
            if (is("n")) {
                atom();
                foot = is("lf") ? FootForce.Foot.LEFT : is("rf") ? FootForce.Foot.RIGHT
                        : is("lf1") ? FootForce.Foot.LEFT_TOE : is("rf1") ? FootForce.Foot.RIGHT_TOE : null;
                name = foot != null ? foot.wireName() : tokenString();
            } else if (is("c")) {
                c = vector();
            } else if (is("f")) {
                f = vector();
            } else {
                skipRestAfterAtom();
            }
            close();
        }
        close();
        if (name == null || c == null || f == null) throw new MalformedMessageException("FRP needs n, c and f", pos);
        if (foot == null) {
            logOnce("frp " + name, "unknown FRP '" + name + "' ignored");
            return null;
        }
        return new FootForce(foot, c, f);
    }

    private Vision parseSee() throws MalformedMessageException {
        Polar[] landmarks = new Polar[Landmark.COUNT];
        Polar ball = null;
        List<SeenPlayer> players = List.of();
        List<SeenLine> lines = List.of();
        Vector3 myPos = null, ballPos = null;
        double myOrien = Double.NaN;
        while (peekOpen()) {
            open();
            atom();
            Landmark lm = Landmark.fromBytes(b, tokStart, tokLen);
            if (lm != null) {
                landmarks[lm.ordinal()] = polarList();
                close();
            } else if (is("B")) {
                ball = polarList();
                close();
            } else if (is("P")) {
                if (players.isEmpty()) players = new ArrayList<>(4);
                players.add(parsePlayer());
            } else if (is("L")) {
                Polar s = polarList();
                Polar e = polarList();
                close();
                if (lines.isEmpty()) lines = new ArrayList<>(16);
                lines.add(new SeenLine(s, e));
            } else if (is("mypos")) {
                myPos = vector();
                close();
            } else if (is("myorien")) {
                myOrien = number();
                close();
            } else if (is("ballpos")) {
                ballPos = vector();
                close();
            } else {
                logOnce("see " + tokenString(), "unknown See item '" + tokenString() + "' ignored");
                skipRestAfterAtom();
                close();
            }
        }
        close();
        return new Vision(landmarks, ball, players, lines, myPos, myOrien, ballPos);
    }

    /** (P (team T) (id N) (head (pol d h v)) (rlowerarm ...) ...), already past "P". */
    private SeenPlayer parsePlayer() throws MalformedMessageException {
        String team = null;
        int id = 0;
        Polar[] parts = new Polar[BodyPart.COUNT];
        while (peekOpen()) {
            open();
            atom();
            if (is("team")) {
                atom();
                team = teamName();
                close();
            } else if (is("id")) {
                id = integer();
                close();
            } else {
                BodyPart part = BodyPart.fromBytes(b, tokStart, tokLen);
                if (part == null) {
                    logOnce("part " + tokenString(), "unknown body part '" + tokenString() + "' ignored");
                    skipRestAfterAtom();
                } else {
                    parts[part.ordinal()] = polarList();
                }
                close();
            }
        }
        close();
        return new SeenPlayer(team == null ? "" : team, id, parts);
    }

    /**
     * (hear TEAM TIME self|DIR MSG) on 0.7 servers, (hear TIME self|DIR MSG) on older ones.
     * The message itself may look like a number, so the format is told by the atom count.
     */
    private Hear parseHear() throws MalformedMessageException {
        int[] starts = hearStarts, lens = hearLens;
        int n = 0;
        skipWs();
        while (pos < end && b[pos] != ')') {
            if (b[pos] == '(') throw new MalformedMessageException("nested list in hear", pos);
            atom();
            if (n == 5) throw new MalformedMessageException("too many atoms in hear", tokStart);
            starts[n] = tokStart;
            lens[n] = tokLen;
            n++;
            skipWs();
        }
        close();
        int i = 0;
        String team = null;
        if (n == 4) {
            tokStart = starts[0];
            tokLen = lens[0];
            team = teamName();
            i = 1;
        } else if (n != 3) {
            throw new MalformedMessageException("hear needs 3 or 4 atoms, got " + n, pos);
        }
        double time = numberAt(starts[i], lens[i]);
        boolean self;
        double dir = Double.NaN;
        tokStart = starts[i + 1];
        tokLen = lens[i + 1];
        if (is("self")) {
            self = true;
        } else {
            self = false;
            dir = numberAt(starts[i + 1], lens[i + 1]);
        }
        String msg = new String(b, starts[i + 2], lens[i + 2], StandardCharsets.ISO_8859_1);
        return new Hear(team, time, self, dir, msg);
    }

    // ---- small pieces --------------------------------------------------------------------------

    /** (pol d h v) as the next list. */
    private Polar polarList() throws MalformedMessageException {
        open();
        atom();
        if (!is("pol")) throw new MalformedMessageException("expected (pol d h v)", tokStart);
        double d = number(), h = number(), v = number();
        close();
        return new Polar(d, h, v);
    }

    private Vector3 vector() throws MalformedMessageException {
        double x = number(), y = number(), z = number();
        return new Vector3(x, y, z);
    }

    private String teamName() {
        for (int i = 0; i < teamBytes.length; i++) {
            byte[] t = teamBytes[i];
            if (t == null) {
                teamBytes[i] = Arrays.copyOfRange(b, tokStart, tokStart + tokLen);
                return teamNames[i] = tokenString();
            }
            if (Arrays.equals(t, 0, t.length, b, tokStart, tokStart + tokLen)) return teamNames[i];
        }
        return tokenString();
    }

    private String tokenString() {
        return new String(b, tokStart, tokLen, StandardCharsets.ISO_8859_1);
    }

    private boolean is(String s) {
        if (s.length() != tokLen) return false;
        for (int i = 0; i < tokLen; i++) if (b[tokStart + i] != s.charAt(i)) return false;
        return true;
    }

    private void skipWs() {
        while (pos < end) {
            byte c = b[pos];
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != 0) break;
            pos++;
        }
    }

    private boolean peekOpen() {
        skipWs();
        return pos < end && b[pos] == '(';
    }

    private void open() throws MalformedMessageException {
        skipWs();
        if (pos >= end) throw new MalformedMessageException("message ends where '(' was expected", pos);
        if (b[pos] != '(') throw new MalformedMessageException("expected '('", pos);
        pos++;
    }

    private void close() throws MalformedMessageException {
        skipWs();
        if (pos >= end) throw new MalformedMessageException("message ends where ')' was expected", pos);
        if (b[pos] != ')') throw new MalformedMessageException("expected ')'", pos);
        pos++;
    }

    /** Reads one atom (a run of bytes up to whitespace or a parenthesis) into tokStart/tokLen. */
    private void atom() throws MalformedMessageException {
        skipWs();
        int s = pos;
        while (pos < end) {
            byte c = b[pos];
            if (c == '(' || c == ')' || c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == 0) break;
            pos++;
        }
        if (pos == s) {
            throw new MalformedMessageException(pos >= end ? "message ends where a name was expected"
                    : "expected a name, found '" + (char) b[pos] + "'", pos);
        }
        tokStart = s;
        tokLen = pos - s;
    }

    /** Skips the rest of the current list up to, not including, its closing parenthesis. */
    private void skipRestAfterAtom() throws MalformedMessageException {
        int depth = 0;
        while (pos < end) {
            byte c = b[pos];
            if (c == '(') {
                depth++;
            } else if (c == ')') {
                if (depth == 0) return;
                depth--;
            }
            pos++;
        }
        throw new MalformedMessageException("unbalanced parentheses", pos);
    }

    /** Skips the rest of the current list including its closing parenthesis. */
    private void skipRest() throws MalformedMessageException {
        skipRestAfterAtom();
        pos++;
    }

    private int integer() throws MalformedMessageException {
        atom();
        long v = 0;
        int i = tokStart, e = tokStart + tokLen;
        boolean neg = b[i] == '-';
        if (neg || b[i] == '+') i++;
        if (i == e || e - i > 9) throw new MalformedMessageException("expected an integer", tokStart);
        for (; i < e; i++) {
            int d = b[i] - '0';
            if (d < 0 || d > 9) throw new MalformedMessageException("expected an integer", tokStart);
            v = v * 10 + d;
        }
        return (int) (neg ? -v : v);
    }

    private double number() throws MalformedMessageException {
        atom();
        return numberAt(tokStart, tokLen);
    }

    /**
     * Decimal numbers as the server prints them ("-0.00", "18.70"), without allocating; anything
     * longer or with an exponent goes through Double.parseDouble. "nan" and "inf" (C printf) are
     * accepted: consumers check finiteness where it matters.
     */
    private double numberAt(int start, int len) throws MalformedMessageException {
        int i = start, e = start + len;
        boolean neg = false;
        if (b[i] == '-' || b[i] == '+') {
            neg = b[i] == '-';
            i++;
        }
        long mant = 0;
        int digits = 0, frac = 0;
        boolean dot = false, simple = true;
        for (; i < e; i++) {
            int c = b[i];
            if (c >= '0' && c <= '9') {
                mant = mant * 10 + (c - '0');
                digits++;
                if (dot) frac++;
            } else if (c == '.' && !dot) {
                dot = true;
            } else {
                simple = false;
                break;
            }
        }
        if (simple && digits > 0 && digits <= 15) {
            double v = frac == 0 ? mant : mant / POW10[frac];
            return neg ? -v : v;
        }
        return slowNumber(start, len);
    }

    private double slowNumber(int start, int len) throws MalformedMessageException {
        String s = new String(b, start, len, StandardCharsets.ISO_8859_1);
        String l = s.toLowerCase();
        if (l.equals("nan") || l.equals("-nan") || l.equals("+nan")) return Double.NaN;
        if (l.equals("inf") || l.equals("+inf") || l.equals("infinity")) return Double.POSITIVE_INFINITY;
        if (l.equals("-inf") || l.equals("-infinity")) return Double.NEGATIVE_INFINITY;
        // Double.parseDouble would also take "1d", "0x1p3" and the like; the server never prints them.
        for (int k = 0; k < len; k++) {
            char c = s.charAt(k);
            if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) {
                throw new MalformedMessageException("expected a number, found '" + s + "'", start);
            }
        }
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException ex) {
            throw new MalformedMessageException("expected a number, found '" + s + "'", start);
        }
    }

    private static void logOnce(String key, String message) {
        if (LOGGED.size() < 1000 && LOGGED.add(key)) LOG.info(message);
    }
}

package phalanx.comm.mj;

import phalanx.comm.sexp.MalformedMessageException;

import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Parses the rcssservermj (rcsssmj 0.2.1) perception dialect into {@link MjPerception}.
 * A single-pass reader over the message: each top-level node is dispatched on its head and read by a small
 * method per node kind; everything else is skipped, its parentheses checked. The plain {@code -12.345}
 * numbers the server sends are read in place (exact: at most 15 digits, so one division of two exact doubles
 * rounds as Double.parseDouble does); any other form goes through Double.parseDouble. Unknown nodes are
 * ignored; every defect (truncation, unbalanced parentheses, nesting deeper than 32, a bad number, a missing
 * child) ends in {@link MalformedMessageException}; a MIC pair that is not an azimuth and base64 is only
 * skipped and counted ({@link MjPerception#heardSkipped}). The results, and which messages are rejected, are those
 * of the tree parser it replaced (TreeReferenceParser in the tests). Not thread-safe: one per thread.
 */
public final class MjPerceptionParser {
    private static final int MAX_DEPTH = 32;
    private static final double[] POW10 = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
            1e13, 1e14, 1e15};

    private String s;
    /** s's chars (read from an array rather than through String.charAt: faster), reused between messages. */
    private char[] c = new char[4096];
    private int n;
    private int p;
    /** The head atom of the list {@link #open} last entered: [headStart, headEnd), empty if it has none. */
    private int headStart, headEnd;
    /** See {@link #name}. */
    private final String[] names = new String[1024];
    /** A See object's (pol D A E), copied into its Seen. */
    private final double[] polar = new double[3];

    private double time, gameTime;
    private String playMode, teamLeft, teamRight;
    private int scoreLeft, scoreRight;
    private double[] quat, pos, gyro, acc;
    private Map<String, double[]> joints;
    private Map<String, Integer> touch;
    private List<MjPerception.Seen> seen;
    private List<MjPerception.Heard> heard;
    private int heardSkipped;

    public MjPerception parse(String message) throws MalformedMessageException {
        s = message;
        n = message.length();
        if (c.length < n) c = new char[Math.max(n, 2 * c.length)];
        message.getChars(0, n, c, 0);
        p = 0;
        time = gameTime = Double.NaN;
        playMode = teamLeft = teamRight = null;
        scoreLeft = scoreRight = 0;
        quat = pos = gyro = acc = null;
        joints = new LinkedHashMap<>(32); // the T1's 23 joints without a rehash
        touch = new LinkedHashMap<>();
        seen = new ArrayList<>();
        heard = new ArrayList<>();
        heardSkipped = 0;
        ws();
        while (p < n) {
            if (c[p] != '(') throw error("expected '('");
            node();
            ws();
        }
        return new MjPerception(time, gameTime, playMode, teamLeft, teamRight, scoreLeft, scoreRight,
                quat, pos, gyro, acc, joints, touch, seen, heard, heardSkipped);
    }

    private void node() throws MalformedMessageException {
        open(0);
        if (headIs("HJ")) joint();
        else if (headIs("time")) time = numbersChild("now", new double[1], 0)[0];
        else if (headIs("GS")) gameState();
        else if (headIs("quat")) quat = numbersChild("q", new double[4], 0);
        else if (headIs("pos")) pos = numbersChild("p", new double[3], 0);
        else if (headIs("GYR")) gyro = numbersChild("rt", new double[3], 0);
        else if (headIs("ACC")) acc = numbersChild("a", new double[3], 0);
        else if (headIs("See")) see();
        else if (headIs("TCH")) touch();
        else if (headIs("MIC")) microphone();
        else close(0);
    }

    /** (HJ (n NAME) (ax DEG) (vx DEG/S)): the first of each child counts, in any order. */
    private void joint() throws MalformedMessageException {
        String name = null;
        double ax = Double.NaN, vx = Double.NaN; // numbers are finite: NaN is "not seen yet"
        while (next()) {
            if (!openChild(1)) continue;
            if (name == null && headIs("n")) name = singleAtom();
            else if (Double.isNaN(ax) && headIs("ax")) ax = singleNumber();
            else if (Double.isNaN(vx) && headIs("vx")) vx = singleNumber();
            else close(1);
        }
        if (name == null || Double.isNaN(ax) || Double.isNaN(vx)) throw error("(HJ) needs (n), (ax) and (vx)");
        joints.put(name, new double[] {ax, vx});
    }

    /** (GS (t T) (pm MODE) (tl NAME) (tr NAME) (sl N) (sr N)): each child's first element; the last child wins. */
    private void gameState() throws MalformedMessageException {
        while (next()) {
            if (!openChild(1)) continue;
            int kind = headIs("t") ? 0 : headIs("pm") ? 1 : headIs("tl") ? 2 : headIs("tr") ? 3
                    : headIs("sl") ? 4 : headIs("sr") ? 5 : -1;
            if (kind < 0) { close(1); continue; }
            if (!next()) continue; // (t) alone is ignored
            if (c[p] == '(') throw error("expected an atom");
            switch (kind) {
                case 0 -> gameTime = number();
                case 1 -> playMode = atom();
                case 2 -> teamLeft = atom();
                case 3 -> teamRight = atom();
                case 4 -> scoreLeft = (int) number();
                default -> scoreRight = (int) number();
            }
            close(1);
        }
    }

    /** (TCH n NAME val 0|1 ...): the third element is the name, the fifth the state. */
    private void touch() throws MalformedMessageException {
        String name = null;
        int state = 0;
        for (int i = 1; i <= 4; i++) {
            if (!next()) throw error("(TCH n name val 0|1) too short");
            boolean list = c[p] == '(';
            if (i == 2 || i == 4) {
                if (list) throw error("expected an atom");
                if (i == 2) name = atom(); else state = (int) number();
            } else if (list) {
                skipList(1);
            } else {
                skipAtom();
            }
        }
        close(0);
        touch.put(name, state);
    }

    /** (See (NAME (pol D A E)) ... (P (team T) (id I) (PART (pol D A E)) ...) ...). */
    private void see() throws MalformedMessageException {
        while (next()) {
            if (!openChild(1)) continue;
            if (headIs("P")) {
                player();
            } else if (headEnd > headStart) {
                String name = name(headStart, headEnd);
                seen.add(seenObject(name, numbersChild("pol", polar, 1)));
            } else {
                close(1);
            }
        }
    }

    /** A seen player (depth 1): one Seen "P team id PART" per part, the first (team) and (id) naming them all. */
    private void player() throws MalformedMessageException {
        String team = null, id = null;
        List<String> parts = new ArrayList<>();
        List<double[]> polars = new ArrayList<>();
        while (next()) {
            if (!openChild(2)) continue;
            if (headIs("team")) {
                if (team == null) team = firstAtom(2); else close(2);
            } else if (headIs("id")) {
                if (id == null) id = firstAtom(2); else close(2);
            } else if (headEnd > headStart && !headIs("P")) {
                parts.add(name(headStart, headEnd));
                polars.add(numbersChild("pol", new double[3], 2));
            } else {
                close(2);
            }
        }
        if (team == null || id == null) throw error("(P) needs (team) and (id)");
        for (int i = 0; i < parts.size(); i++) {
            seen.add(seenObject("P " + team + " " + id + " " + parts.get(i), polars.get(i)));
        }
    }

    private static MjPerception.Seen seenObject(String name, double[] polar) {
        return new MjPerception.Seen(name, polar[0], polar[1], polar[2]);
    }

    /**
     * (MIC NAME (AZIMUTH BASE64) ...), as rcsssmj 0.2.1's MicrophonePerception writes it: atoms (the sensor
     * name, "hear") are skipped; each list child that is exactly a finite number and valid base64 becomes a
     * {@link MjPerception.Heard}, any other is skipped and counted in heardSkipped.
     */
    private void microphone() throws MalformedMessageException {
        while (next()) {
            if (!openChild(1)) continue;
            double azimuth = lenientNumber(headStart, headEnd);
            if (!next()) { heardSkipped++; continue; }
            if (c[p] == '(') { close(1); heardSkipped++; continue; }
            int start = p;
            skipAtom();
            int end = p;
            if (next()) { close(1); heardSkipped++; continue; }
            byte[] bytes = Double.isNaN(azimuth) ? null : base64(s, start, end);
            if (bytes == null) heardSkipped++; else heard.add(new MjPerception.Heard(azimuth, bytes));
        }
    }

    /** s[start, end) as a finite number, NaN if it is none (no exception: a bad MIC pair is only skipped). */
    private double lenientNumber(int start, int end) {
        if (end == start) return Double.NaN;
        try {
            double d = Double.parseDouble(s.substring(start, end));
            return Double.isFinite(d) ? d : Double.NaN;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /**
     * Strict base64 (RFC 4648, padded, as Python's b64encode writes and b64decode(validate=True) reads),
     * null if t[start, end) is not; shared with the reference parser in the tests.
     */
    static byte[] base64(String t, int start, int end) {
        if (end == start || (end - start) % 4 != 0) return null;
        try {
            return Base64.getDecoder().decode(t.substring(start, end));
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    // --- children of the list being read (its head consumed) ---

    /** Reads the rest of a list at depth: v filled from its first child headed name; others are skipped. */
    private double[] numbersChild(String name, double[] v, int depth) throws MalformedMessageException {
        boolean found = false;
        while (next()) {
            if (!openChild(depth + 1)) continue;
            if (!found && headIs(name)) {
                numbers(v);
                found = true;
            } else {
                close(depth + 1);
            }
        }
        if (!found) throw error("missing (" + name + ")");
        return v;
    }

    /** The rest of a list that must hold exactly v.length numbers after its head, into v. */
    private void numbers(double[] v) throws MalformedMessageException {
        for (int i = 0; i < v.length; i++) {
            if (!next()) throw error("needs " + v.length + " numbers");
            if (c[p] == '(') throw error("expected a number");
            v[i] = number();
        }
        if (next()) throw error("needs " + v.length + " numbers");
    }

    /** The rest of a list that must hold exactly one number after its head. */
    private double singleNumber() throws MalformedMessageException {
        if (!next() || c[p] == '(') throw error("expected one number");
        double v = number();
        if (next()) throw error("expected one number");
        return v;
    }

    /** The rest of a list that must hold exactly one atom after its head. */
    private String singleAtom() throws MalformedMessageException {
        if (!next() || c[p] == '(') throw error("(n NAME) expected");
        String a = atom();
        if (next()) throw error("(n NAME) expected");
        return a;
    }

    /** The rest of a list at depth whose first element after the head must be an atom; the rest is skipped. */
    private String firstAtom(int depth) throws MalformedMessageException {
        if (!next() || c[p] == '(') throw error("expected an atom");
        String a = atom();
        close(depth);
        return a;
    }

    // --- the reader ---

    /** At an element: a list is entered ({@link #open}, true); an atom is skipped (false). */
    private boolean openChild(int depth) throws MalformedMessageException {
        if (c[p] != '(') {
            skipAtom();
            return false;
        }
        open(depth);
        return true;
    }

    /** At '(': enters the list (at depth; the top-level ones are 0) and reads its head atom, if it has one. */
    private void open(int depth) throws MalformedMessageException {
        if (depth > MAX_DEPTH) throw error("nesting too deep");
        p++;
        ws();
        headStart = p;
        if (p < n && c[p] != '(' && c[p] != ')') skipAtom();
        headEnd = p;
    }

    private boolean headIs(String name) {
        return headEnd - headStart == name.length() && s.startsWith(name, headStart);
    }

    /** Moves to the next element of the list being read: true there, false past its ')'. */
    private boolean next() throws MalformedMessageException {
        ws();
        if (p >= n) throw error("unexpected end, ')' missing");
        if (c[p] != ')') return true;
        p++;
        return false;
    }

    /** Skips the rest of the list being read (at depth), past its ')'. */
    private void close(int depth) throws MalformedMessageException {
        while (next()) {
            if (c[p] == '(') skipList(depth + 1); else skipAtom();
        }
    }

    private void skipList(int depth) throws MalformedMessageException {
        if (depth > MAX_DEPTH) throw error("nesting too deep");
        p++;
        close(depth);
    }

    // The scanning loops keep the position in a local (the JIT then keeps it in a register).

    private void ws() {
        int i = p;
        while (i < n && whitespace(c[i])) i++;
        p = i;
    }

    private void skipAtom() {
        int i = p;
        while (!atomEnds(i)) i++;
        p = i;
    }

    private boolean atomEnds(int i) {
        return i >= n || c[i] == '(' || c[i] == ')' || whitespace(c[i]);
    }

    private String atom() {
        int start = p;
        skipAtom();
        return name(start, p);
    }

    /**
     * s.substring(start, end), the same String again for the same text: the names (joints, markers, play
     * mode) recur in every message, so a small cache saves a copy per name. Two slots per hash, the newer
     * name first (the T1's ~50 names share a pair of slots rarely, and then both stay).
     */
    private String name(int start, int end) {
        int h = 0;
        for (int i = start; i < end; i++) h = 31 * h + c[i];
        int slot = (h ^ h >>> 9) & (names.length - 2);
        for (int k = slot; k <= slot + 1; k++) {
            String cached = names[k];
            if (cached != null && cached.length() == end - start && s.startsWith(cached, start)) return cached;
        }
        names[slot + 1] = names[slot];
        return names[slot] = s.substring(start, end);
    }

    /**
     * The atom at p as a finite number. [-]digits[.digits] with at most 15 digits is read here: the digits
     * as a long and the power of ten are exact doubles, so the one division is correctly rounded, exactly
     * Double.parseDouble's result. Any other form (exponent, more digits, "5.", junk) goes to Double.parseDouble.
     */
    private double number() throws MalformedMessageException {
        int start = p, i = p;
        boolean negative = c[i] == '-';
        if (negative) i++;
        long digits = 0;
        int count = 0, point = -1;
        for (; i < n; i++) {
            char ch = c[i];
            if (ch >= '0' && ch <= '9') {
                digits = digits * 10 + (ch - '0');
                count++;
            } else if (ch == '.' && point < 0 && count > 0) {
                point = count;
            } else {
                break;
            }
        }
        p = i;
        if (atomEnds(i) && count > 0 && count <= 15 && point != count) {
            double v = point < 0 ? digits : digits / POW10[count - point];
            return negative ? -v : v;
        }
        skipAtom();
        return parseDouble(start, p);
    }

    private double parseDouble(int start, int end) throws MalformedMessageException {
        double d;
        try {
            d = Double.parseDouble(s.substring(start, end));
        } catch (NumberFormatException e) {
            throw new MalformedMessageException("bad number " + s.substring(start, end), start);
        }
        if (!Double.isFinite(d)) {
            throw new MalformedMessageException("non-finite number " + s.substring(start, end), start);
        }
        return d;
    }

    /** Character.isWhitespace, with the space and the printable ASCII (never white) answered without the lookup. */
    private static boolean whitespace(char c) {
        return c == ' ' || (c < ' ' || c >= 0x7F) && Character.isWhitespace(c);
    }

    private MalformedMessageException error(String reason) {
        return new MalformedMessageException(reason, p);
    }
}

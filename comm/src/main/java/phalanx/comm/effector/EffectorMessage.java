package phalanx.comm.effector;

import phalanx.comm.perception.Joint;

/**
 * Builds the text a player sends: the one-off scene and init messages, and the per-cycle message
 * of effectors ending in {@code (syn)}. One instance is reused every cycle ({@link #reset()}), so
 * encoding allocates nothing. Hinge velocities are in rad/s, the unit rcssserver3d expects
 * (the thesis says degrees; the server says radians: recordings README).
 */
public final class EffectorMessage {
    /** Longest say message the server delivers; longer ones are dropped silently (S4, k = 250). */
    public static final int MAX_SAY_LENGTH = 20;

    private final StringBuilder sb = new StringBuilder(1024);

    /** {@code (scene rsg/agent/nao/nao_hetero.rsg T)} for type 0-4, {@code nao.rsg} for type -1. */
    public static String scene(int robotType) {
        if (robotType == -1) return "(scene rsg/agent/nao/nao.rsg)";
        if (robotType < 0 || robotType > 4) throw new IllegalArgumentException("robot type must be 0-4 (or -1 for nao.rsg), got " + robotType);
        return "(scene rsg/agent/nao/nao_hetero.rsg " + robotType + ")";
    }

    /** {@code (init (unum N)(teamname T))(syn)}; unum 0 lets the server choose. */
    public static String init(int unum, String team) {
        if (unum < 0 || unum > 11) throw new IllegalArgumentException("unum must be 0-11, got " + unum);
        if (team == null || team.isEmpty() || !isAtom(team)) {
            throw new IllegalArgumentException("team name must be non-empty printable ASCII without space or parentheses: '" + team + "'");
        }
        return "(init (unum " + unum + ")(teamname " + team + "))(syn)";
    }

    public EffectorMessage reset() {
        sb.setLength(0);
        return this;
    }

    /** {@code (beam x y rot)}: own-frame metres and degrees (a right team's frame is turned by 180°). */
    public EffectorMessage beam(double x, double y, double rotDeg) {
        requireFinite(x, "beam x");
        requireFinite(y, "beam y");
        requireFinite(rotDeg, "beam rotation");
        sb.append("(beam ");
        number(x);
        sb.append(' ');
        number(y);
        sb.append(' ');
        number(rotDeg);
        sb.append(')');
        return this;
    }

    /** {@code (he1 v)}: target angular velocity of one hinge joint in rad/s. */
    public EffectorMessage hinge(Joint joint, double radPerSecond) {
        // the message is built only on failure: this runs 22 times a cycle
        if (!Double.isFinite(radPerSecond)) requireFinite(radPerSecond, joint.effectorName() + " velocity");
        sb.append('(').append(joint.effectorName()).append(' ');
        number(radPerSecond);
        sb.append(')');
        return this;
    }

    /** {@code (say msg)}; refuses what the server would drop, naming the reason. */
    public EffectorMessage say(String message) {
        String problem = sayProblem(message);
        if (problem != null) throw new IllegalArgumentException("say refused: " + problem);
        sb.append("(say ").append(message).append(')');
        return this;
    }

    public EffectorMessage syn() {
        sb.append("(syn)");
        return this;
    }

    public CharSequence text() { return sb; }

    @Override public String toString() { return sb.toString(); }

    /**
     * Why the server would not deliver this say message, or null if it would: 1-20 characters,
     * printable ASCII (0x21-0x7e) except '(' and ')'.
     */
    public static String sayProblem(String message) {
        if (message == null || message.isEmpty()) return "empty message";
        if (message.length() > MAX_SAY_LENGTH) {
            return "'" + message + "' has " + message.length() + " characters, the server delivers at most " + MAX_SAY_LENGTH;
        }
        for (int i = 0; i < message.length(); i++) {
            char c = message.charAt(i);
            if (c <= 0x20 || c >= 0x7f || c == '(' || c == ')') {
                return "character " + (c < 0x20 || c >= 0x7f ? String.format("0x%02x", (int) c) : "'" + c + "'")
                        + " at position " + i + " of '" + message + "' is not allowed (printable ASCII without space and parentheses)";
            }
        }
        return null;
    }

    private static boolean isAtom(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c <= 0x20 || c >= 0x7f || c == '(' || c == ')') return false;
        }
        return true;
    }

    private static void requireFinite(double v, String what) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException(what + " must be finite, got " + v);
    }

    /** Four decimals, no allocation; the server reads C floats, so that is far below its noise. */
    private void number(double v) {
        long scaled = Math.round(v * 10_000);
        if (scaled < 0) {
            sb.append('-');
            scaled = -scaled;
        }
        long whole = scaled / 10_000, frac = scaled % 10_000;
        sb.append(whole);
        if (frac != 0) {
            sb.append('.');
            if (frac < 1000) sb.append('0');
            if (frac < 100) sb.append('0');
            if (frac < 10) sb.append('0');
            while (frac % 10 == 0) frac /= 10;
            sb.append(frac);
        }
    }
}

package phalanx.comm.mj;

import java.util.Base64;
import java.util.List;
import java.util.Locale;

/** Builds rcssservermj action messages: init, beam, T1 joint PD commands in degrees, and say. */
public final class MjActions {
    /** The T1's actuator names in rcsssmj 0.2.1. */
    public static final List<String> T1_ACTUATORS = List.of("he1", "he2", "lae1", "lae2", "lae3", "lae4",
            "rae1", "rae2", "rae3", "rae4", "te1", "lle1", "lle2", "lle3", "lle4", "lle5", "lle6",
            "rle1", "rle2", "rle3", "rle4", "rle5", "rle6");

    private final StringBuilder sb = new StringBuilder();

    public static String init(String team, int number) {
        if (team.isEmpty() || !team.chars().allMatch(c -> c > ' ' && c < 127 && c != '(' && c != ')')) {
            throw new IllegalArgumentException("bad team name: " + team);
        }
        return "(init T1 " + team + " " + number + ")";
    }

    public static String beam(double x, double y, double thetaDeg) {
        return String.format(Locale.ROOT, "(beam %s %s %s)", f(x), f(y), f(thetaDeg));
    }

    /** Appends {@code (<actuator> q_deg dq_deg kp kd tau)}. */
    public MjActions joint(String actuator, double qDeg, double dqDeg, double kp, double kd, double tau) {
        if (!T1_ACTUATORS.contains(actuator)) throw new IllegalArgumentException("unknown T1 actuator " + actuator);
        sb.append('(').append(actuator).append(' ').append(f(qDeg)).append(' ').append(f(dqDeg)).append(' ')
                .append(f(kp)).append(' ').append(f(kd)).append(' ').append(f(tau)).append(')');
        return this;
    }

    /** rcsssmj 0.2.1 delivers a said message only if it has at most this many bytes. */
    public static final int MAX_SAY_BYTES = 10;

    /**
     * Appends {@code (SPK say 100 <base64>)}: the message at full volume (the server's gain is volume / 100,
     * capped at 1). Refuses an empty message (the server broadcasts none) and one of more than
     * {@value #MAX_SAY_BYTES} bytes (the server would send it but no one would hear it).
     */
    public MjActions say(byte[] message) {
        if (message == null || message.length == 0) throw new IllegalArgumentException("say needs at least one byte");
        if (message.length > MAX_SAY_BYTES) {
            throw new IllegalArgumentException("say carries at most " + MAX_SAY_BYTES + " bytes, got " + message.length);
        }
        sb.append("(SPK say 100 ").append(Base64.getEncoder().encodeToString(message)).append(')');
        return this;
    }

    /** The message so far, {@code (syn)} if empty; resets the builder. */
    public String build() {
        String out = sb.length() == 0 ? "(syn)" : sb.toString();
        sb.setLength(0);
        return out;
    }

    private static String f(double v) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite value " + v);
        String s = String.format(Locale.ROOT, "%.4f", v);
        s = s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
        return s.equals("-0") ? "0" : s;
    }
}

package phalanx.comm.team;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Map;

/**
 * The per-match secret shared by our eleven players: start.sh draws one for each match and passes it
 * to every player in the environment variable {@value #ENVIRONMENT_VARIABLE}. Opponents hear all we
 * say but not this key, so they can neither forge a message nor (with the time slot in the check)
 * replay one. The 128-bit SipHash key is the first 16 bytes of SHA-256 over the secret's UTF-8 text.
 */
public final class TeamKey {
    public static final String ENVIRONMENT_VARIABLE = "PHALANX_TEAM_KEY";
    /** Short secrets could be guessed offline from one heard message; start.sh uses 32 hex digits. */
    public static final int MIN_SECRET_LENGTH = 16;

    final long k0, k1;

    private TeamKey(long k0, long k1) {
        this.k0 = k0;
        this.k1 = k1;
    }

    /** The key for this secret; refuses null, blank and short secrets with a message saying which. */
    public static TeamKey fromSecret(String secret) {
        if (secret == null || secret.isBlank()) {
            throw new IllegalArgumentException("team key is empty: start.sh passes a per-match secret in "
                    + ENVIRONMENT_VARIABLE + " (e.g. 32 hex digits from /dev/urandom)");
        }
        if (secret.length() < MIN_SECRET_LENGTH) {
            throw new IllegalArgumentException("team key has " + secret.length() + " characters, at least "
                    + MIN_SECRET_LENGTH + " are needed so opponents cannot guess it from what they hear");
        }
        byte[] digest;
        try {
            digest = MessageDigest.getInstance("SHA-256").digest(secret.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is required of every Java platform", e);
        }
        return new TeamKey(SipHash.littleEndian(digest, 0, 8), SipHash.littleEndian(digest, 8, 8));
    }

    /** The key from {@value #ENVIRONMENT_VARIABLE} in this environment (pass {@code System.getenv()}). */
    public static TeamKey fromEnvironment(Map<String, String> environment) {
        String secret = environment.get(ENVIRONMENT_VARIABLE);
        if (secret == null) {
            throw new IllegalArgumentException(ENVIRONMENT_VARIABLE + " is not set: start.sh passes the per-match team key "
                    + "to every player; without it team messages cannot be checked");
        }
        try {
            return fromSecret(secret);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(ENVIRONMENT_VARIABLE + ": " + e.getMessage(), e);
        }
    }

    /** Raw 128-bit key, little-endian halves (for the SipHash test vectors). */
    static TeamKey ofRaw(long k0, long k1) {
        return new TeamKey(k0, k1);
    }

    @Override public String toString() {
        return "TeamKey[hidden]";
    }
}

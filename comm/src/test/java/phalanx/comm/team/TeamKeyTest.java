package phalanx.comm.team;

import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

class TeamKeyTest {

    @Test
    void missingEnvironmentVariableIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TeamKey.fromEnvironment(Map.of()));
        assertTrue(e.getMessage().contains("PHALANX_TEAM_KEY is not set"), e.getMessage());
    }

    @Test
    void shortAndBlankSecretsAreRefusedWithTheReason() {
        IllegalArgumentException shortKey = assertThrows(IllegalArgumentException.class,
                () -> TeamKey.fromEnvironment(Map.of(TeamKey.ENVIRONMENT_VARIABLE, "abc")));
        assertTrue(shortKey.getMessage().contains("PHALANX_TEAM_KEY: team key has 3 characters, at least 16"), shortKey.getMessage());
        IllegalArgumentException blank = assertThrows(IllegalArgumentException.class, () -> TeamKey.fromSecret("   "));
        assertTrue(blank.getMessage().contains("team key is empty"), blank.getMessage());
        assertThrows(IllegalArgumentException.class, () -> TeamKey.fromSecret(null));
    }

    @Test
    void sameSecretSameKeyOtherSecretOtherKey() {
        TeamKey a = TeamKey.fromSecret("0123456789abcdef0123456789abcdef");
        TeamKey b = TeamKey.fromEnvironment(Map.of(TeamKey.ENVIRONMENT_VARIABLE, "0123456789abcdef0123456789abcdef"));
        TeamKey c = TeamKey.fromSecret("0123456789abcdef0123456789abcdee");
        assertEquals(a.k0, b.k0);
        assertEquals(a.k1, b.k1);
        assertNotEquals(a.k0, c.k0);
        assertEquals("TeamKey[hidden]", a.toString());
    }
}

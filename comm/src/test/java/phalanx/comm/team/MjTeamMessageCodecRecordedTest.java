package phalanx.comm.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.mj.MjPerceptionParser;
import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/**
 * MjTeamMessageCodec over what rcssservermj delivered (t1-hear.txt, see the resources README): Phalanx 2
 * said {@link #expected}(c) encoded with {@link #KEY} in reply to each perception c, except for a replay
 * (c mod 20 = 7: the frame of c - 5 again), a forgery (13: 10 random bytes), a truncation (17: the first
 * 9 bytes) and an 11-byte frame (19); Other 1 said a Location encoded with its own key on even cycles;
 * the hearer, Phalanx 1, said Init(1) on cycles divisible by 10.
 */
class MjTeamMessageCodecRecordedTest {
    static final TeamKey KEY = TeamKey.fromSecret("rcssservermj-fixture-key-0001");
    static final TeamKey OTHER = TeamKey.fromSecret("another-teams-key-not-ours-0002");

    /** What Phalanx 2 said in reply to perception s (the scratch recorder has the same function). */
    static TeamMessage expected(long s) {
        int k = Math.floorMod(s, 6);
        double a = Math.floorMod(s * 37, 500) / 10.0 - 25, b = Math.floorMod(s * 53, 340) / 10.0 - 17;
        double th = Math.floorMod(s * 29, 360) - 180;
        return switch (k) {
            case 0 -> new TeamMessage.Complete(2, a, b, th, -a / 2, -b / 2);
            case 1 -> new TeamMessage.Location(2, a, b, th);
            case 2 -> new TeamMessage.Ball(2, Math.abs(a) + 0.5, th);
            case 3 -> new TeamMessage.Unaware(2, s % 2 == 0);
            case 4 -> new TeamMessage.Actions(0, List.of(Action.walkTo(3, a, b, th), Action.of(4, ActionId.ON_BALL)));
            default -> new TeamMessage.Init(2);
        };
    }

    static List<String> recording() throws Exception {
        try (InputStream in = MjTeamMessageCodecRecordedTest.class.getResourceAsStream("/rcssservermj/t1-hear.txt")) {
            return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1).lines().toList();
        }
    }

    @Test
    void everyTeamMateFrameIsAcceptedAndEverythingElseRejected() throws Exception {
        MjPerceptionParser parser = new MjPerceptionParser();
        MjTeamMessageCodec codec = new MjTeamMessageCodec(KEY, ChannelConfig.DEFAULT);
        MjTeamMessageCodec ours = new MjTeamMessageCodec(KEY, ChannelConfig.DEFAULT);
        MjTeamMessageCodec theirs = new MjTeamMessageCodec(OTHER, ChannelConfig.DEFAULT);
        int accepted = 0, replays = 0, forged = 0, truncated = 0, foreign = 0, emptyMics = 0;
        Map<Rejection, Integer> foreignReasons = new EnumMap<>(Rejection.class);
        for (String line : recording()) {
            MjPerception p = parser.parse(line);
            long heard = MjTeamMessageCodec.cycleOf(p.time());
            long s = heard - 2; // measured: said in reply to perception c, heard in c + 2
            if (line.contains("(MIC hear )")) {
                emptyMics++;
                assertEquals(19, Math.floorMod(s, 20), "only the 11-byte frame leaves an empty MIC (heard " + heard + ")");
            }
            for (MjPerception.Heard h : p.heard()) {
                byte[] bytes = h.bytes();
                Decoded d = codec.decode(bytes, heard);
                assertNotNull(d);
                byte[] mine = ours.encode(expected(s), s);
                int special = Math.floorMod(s, 20);
                if (s % 2 == 0 && Arrays.equals(bytes, theirs.encode(new TeamMessage.Location(1, 1, 2, 3), s))) {
                    foreign++;
                    assertFalse(d.accepted());
                    foreignReasons.merge(d.rejection(), 1, Integer::sum);
                } else if (special == 7) {
                    replays++;
                    assertArrayEquals(ours.encode(expected(s - 5), s - 5), bytes);
                    assertEquals(Rejection.BAD_CHECK, d.rejection()); // its cycle bits fit s - 1, its check does not
                } else if (special == 13) {
                    forged++;
                    assertFalse(d.accepted());
                } else if (special == 17) {
                    truncated++;
                    assertArrayEquals(Arrays.copyOf(mine, 9), bytes);
                    assertEquals(Rejection.TOO_SHORT, d.rejection());
                } else {
                    accepted++;
                    assertArrayEquals(mine, bytes, "heard " + heard);
                    assertTrue(d.accepted(), () -> "heard " + heard + ": " + d.rejection());
                    assertEquals(s, d.saidCycle());
                    TeamMessage m = d.message();
                    assertEquals(expected(s).getClass(), m.getClass());
                    assertArrayEquals(mine, ours.encode(m, s), "re-encodes to the same frame");
                    assertFalse(m instanceof TeamMessage.Init i && i.sender() == 1, "the hearer heard itself");
                }
            }
        }
        // 98 perceptions with a MIC (the first two have none): 93 of Phalanx 2's frames, 5 empty MICs (11 bytes)
        assertEquals(93 - 5 - 5 - 5, accepted, "accepted");
        assertEquals(5, replays);
        assertEquals(5, forged);
        assertEquals(5, truncated);
        assertEquals(5, emptyMics);
        // Other 1 joined a cycle later and spoke on even cycles; its frames follow the same clock, so only
        // the check tells them from ours (rcsssmj does not say who spoke)
        assertEquals(48, foreign);
        assertEquals(Map.of(Rejection.BAD_CHECK, 48), foreignReasons);
    }
}

package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.model.field.MjField;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** MjRuntime over the real recording (comm/src/test/resources/rcssservermj) and over broken input. */
class MjRuntimeTest {
    private static final Path RECORDING = Path.of("comm/src/test/resources/rcssservermj/t1-standing.txt");

    @Test
    void answersEveryRecordedMessageWithAllT1JointsAndBeamsFirst() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        String first = r.update(lines.get(0));
        assertTrue(first.startsWith("(beam "), "off the field before kick-off: beam first, got " + first.substring(0, 30));
        for (String a : List.of("lle4", "rle4", "lle5", "rle5")) assertTrue(first.contains("(" + a + " "), a + " commanded");
        for (String line : lines.subList(1, lines.size())) {
            String reply = r.update(line);
            assertTrue(reply.startsWith("(") && reply.endsWith(")"), reply);
        }
        assertEquals(lines.size(), r.cycles());
        assertEquals(0, r.malformed());
        assertTrue(r.beams() >= 1);
    }

    @Test
    void aBrokenMessageIsCountedAndAnsweredWithTheLastCommands() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        r.update(lines.get(5));
        // a say is never repeated (it would be a replay): the joint commands only
        String good = r.update(lines.get(6)).replaceAll("\\(SPK [^)]*\\)", "");
        String line = lines.get(7);
        for (String broken : List.of(line.substring(0, line.length() / 2), "(time (now 1.0)", ")))", "(pos (n torso_pos) (p a b c))", "")) {
            String reply = r.update(broken);
            assertEquals(good, reply, "the last joint commands again for '" + broken + "'");
        }
        assertEquals(4, r.malformed(), "the empty message is a valid (empty) perception, the other four are not");
        for (String q : List.of("0 0 0 0", "NaN 0 0 1", "2 0 0 0")) {
            String reply = r.update(line.replaceAll("\\(q [^)]*\\)", "(q " + q + ")"));
            assertEquals(good, reply, "a torso quaternion (" + q + ") that is no rotation: the last commands again");
        }
        assertEquals(7, r.malformed(), "and each is counted");
    }

    @Test
    void foreignAndBrokenHeardMessagesAreDroppedAndThePlayerPlaysOn() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        var them = new phalanx.comm.team.MjTeamMessageCodec(phalanx.comm.team.TeamKey.fromSecret("the-other-teams-key-123"),
                phalanx.comm.team.ChannelConfig.MJ);
        java.util.Base64.Encoder b64 = java.util.Base64.getEncoder();
        for (int k = 0; k < 20; k++) {
            String line = lines.get(k);
            long cycle = phalanx.comm.team.MjTeamMessageCodec.cycleOf(Double.parseDouble(line.replaceAll("^.*?\\(now ([0-9.]+)\\).*$", "$1")));
            // an opponent's order to player 2 said two cycles ago, random bytes, too short, too long, not base64
            String mic = "(MIC hear (0 " + b64.encodeToString(them.encode(new phalanx.comm.team.TeamMessage.Actions(0,
                    List.of(phalanx.comm.team.Action.walkTo(2, 30, 20, 0))), cycle - 2)) + ")(45 " + b64.encodeToString(new byte[] {9, 8, 7, 6, 5, 4, 3, 2, 1, 0})
                    + ")(90 AQID)(135 " + b64.encodeToString(new byte[11]) + ")(180 not-base64!))";
            String reply = assertDoesNotThrow(() -> r.update(line + mic));
            assertTrue(reply.startsWith("(") && reply.endsWith(")"), reply);
        }
        assertEquals(0, r.malformed(), "a bad heard message is not a bad perception");
        assertNull(r.channel().order(), "no order from another team");
        var c = r.channel();
        assertEquals(20, c.rejected(phalanx.comm.team.TeamMessageCodec.Rejection.TOO_SHORT));
        assertEquals(20, c.rejected(phalanx.comm.team.TeamMessageCodec.Rejection.TOO_LONG));
        assertEquals(40, c.rejected(phalanx.comm.team.TeamMessageCodec.Rejection.BAD_CHECK) + c.rejected(phalanx.comm.team.TeamMessageCodec.Rejection.WRONG_TIME),
                "the opponent's order and the random frame fail the check (or the cycle bits)");
    }

    @Test
    void strangeSeenPlayersAreAnsweredAndNeverStopThePlayer() throws Exception {
        MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
        List<String> lines = Files.readAllLines(RECORDING);
        String[] players = {
                "(P (team Other)(id 1)(lfoot (pol NaN 0 0))(head (pol 1e308 -1e308 5)))",   // not numbers, absurdly far
                "(P (team X)(id y)(rfoot (pol 0.2 0 -80))(rfoot (pol 0.3 1 -70)))",         // an id that is no number, a part twice
                "(P (team Phalanx)(id 2)(lfoot (pol 1 2 3)))",                              // "ourselves"
                "(P (team Other)(id 1))", "(P (id 3)(head (pol 1 0 0)))", "(P)",            // no parts; no team; nothing
                "(P (team Other)(id 4)(lfoot (pol 1 2)))", "(P (team Other)(id 5)(lfoot (pol a b c)))"};
        List<String> seeing = lines.stream().filter(l -> l.contains("(See ")).toList();
        StringBuilder skipped = new StringBuilder();
        for (int i = 0; i < 2 * players.length; i++) {
            String p = players[i % players.length];
            String message = seeing.get(10 + i).replace("(pm BeforeKickOff)", "(pm PlayOn)").replace("(See ", "(See " + p);
            long before = r.malformed();
            String reply = assertDoesNotThrow(() -> r.update(message), p);
            assertTrue(reply.startsWith("(") && reply.endsWith(")"), reply);
            if (r.malformed() > before && i < players.length) skipped.append(i).append(' ');
        }
        System.out.println("MjRuntimeTest: strange seen players the parser refuses (skipped whole): " + skipped);
        assertEquals(2 * players.length, r.cycles());
        assertTrue(r.world().players().stream().anyMatch(q -> q.id().equals("y") && !q.mate()), "a well-formed one is seen: " + r.world().players());
        assertTrue(r.world().players().stream().allMatch(q -> q.parts().stream().allMatch(v -> v.isFinite())), "" + r.world().players());
    }

    /** A recorded message in play with the torso lying (quaternion w x y z), still, every joint at 0. */
    private static String lying(String recorded, String quat) {
        return recorded.replace("(pm BeforeKickOff)", "(pm PlayOn)").replaceAll("\\(q [^)]*\\)", "(q " + quat + ")")
                .replaceAll("\\(rt [^)]*\\)", "(rt 0 0 0)");
    }

    /** The first cycle's command for an actuator: q in degrees. */
    private static double commandDeg(String reply, String actuator) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\(" + actuator + " (-?[0-9.]+)").matcher(reply);
        assertTrue(m.find(), actuator + " in " + reply);
        return Double.parseDouble(m.group(1));
    }

    @Test
    void aPlayerLyingInPlayGetsUpWithTheMotionForTheSideItLiesOn() throws Exception {
        String line = Files.readAllLines(RECORDING).get(10).replaceAll("\\(ax [^)]*\\)", "(ax 0)");
        var dir = Path.of("motions", "t1");
        for (String side : List.of("front", "back")) {
            MjRuntime r = new MjRuntime("Phalanx", 2, MjField.SSIM);
            // face down: the torso's x axis points down (pitched +90 deg about y); face up: -90
            String reply = r.update(lying(line, side.equals("front") ? "0.7071 0 0.7071 0" : "0.7071 0 -0.7071 0"));
            assertEquals(1, r.getUps(), side + ": lying still in play starts a get-up at once");
            var m = phalanx.motion.t1.T1MotionLoader.load(dir.resolve("get_up_" + side + ".motion"));
            var player = new phalanx.motion.t1.T1MotionPlayer(0.02, phalanx.motion.t1.T1MotionPlayer.Gains.DEFAULT);
            player.start(m, a -> 0);
            var first = player.next().stream().filter(c -> c.actuator().equals("lle1")).findFirst().orElseThrow();
            assertEquals(first.qDeg(), commandDeg(reply, "lle1"), 0.01, side + ": the hip follows get_up_" + side + ".motion");
            int cycles = (int) Math.round(m.seconds() / 0.02);
            for (int i = 1; i < cycles; i++) r.update(lying(line, "0.7071 0 0.7071 0"));
            assertEquals(1, r.getUps(), "one get-up plays to its end");
            r.update(lying(line, "0.7071 0 0.7071 0"));
            assertEquals(2, r.getUps(), "still down at its end: the next one starts");
            assertEquals(1, r.getUpRetries(), "and counts as a retry");
        }
        MjRuntime up = new MjRuntime("Phalanx", 2, MjField.SSIM);
        up.update(lying(line, "0.7071 0 0 -0.7071"));
        assertEquals(0, up.getUps(), "upright (turned about z only): no get-up");
    }

    @Test
    void aBadGetUpFileStopsThePlayerAtItsStartWithItsName(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("get_up_front.motion"), "#WEBOTS_MOTION,V1.0\nLeft_Knee_Pitch\n00:00:100,bend,-1\n");
        Files.copy(Path.of("motions", "t1", "get_up_back.motion"), dir.resolve("get_up_back.motion"));
        var e = assertThrows(phalanx.motion.MotionFileException.class,
                () -> new MjRuntime("Phalanx", 2, MjField.SSIM, phalanx.agent.Player.teamKey("Phalanx"), dir));
        assertTrue(e.getMessage().contains("get_up_front.motion") && e.getMessage().contains("Left_Knee_Pitch"), e.getMessage());
    }

    @Test
    void aUniformNumberBeyondTheRuleBookIsRefusedBeforeConnecting() {
        int status = MjPlayer.run(phalanx.agent.PlayerOptions.parse("--server", "mj", "--unum", "9", "--connect-timeout", "0"));
        assertEquals(2, status, "ssim has 7 players a side");
    }
}

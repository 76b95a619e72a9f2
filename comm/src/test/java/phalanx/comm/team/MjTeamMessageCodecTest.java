package phalanx.comm.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjActions;
import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class MjTeamMessageCodecTest {
    static final TeamKey KEY = TeamKey.fromSecret("match-key-for-tests-0001");
    static final ChannelConfig CONFIG = ChannelConfig.DEFAULT;
    // Within half a grid step of what was sent: x 6 cm, y 8 cm, angles 1.41°, distances 4 cm.
    static final double X_TOL = 0.03 + 1e-9, Y_TOL = 0.04 + 1e-9, ANGLE_TOL = 360.0 / 256 / 2 + 1e-9, D_TOL = 0.02 + 1e-9;

    private final MjTeamMessageCodec codec = new MjTeamMessageCodec(KEY, CONFIG);

    private TeamMessage roundTrip(TeamMessage m, long said) {
        byte[] frame = codec.encode(m, said);
        assertEquals(10, frame.length);
        new MjActions().say(frame); // sayable
        Decoded d = codec.decode(frame, said + 2);
        assertTrue(d.accepted(), () -> m + " rejected: " + d.rejection());
        assertEquals(said, d.saidCycle());
        Decoded late = codec.decode(frame, said + 3);
        assertTrue(late.accepted(), () -> m + " rejected one cycle late: " + late.rejection());
        assertEquals(d.message(), late.message());
        return d.message();
    }

    static double angleDiff(double a, double b) {
        return Math.abs(Math.IEEEremainder(a - b, 360));
    }

    @Test
    void everyTypeRoundTripsWithinTheGrid() {
        long said = 13512;
        assertEquals(new TeamMessage.Init(7), roundTrip(new TeamMessage.Init(7), said));
        assertEquals(new TeamMessage.Start(1), roundTrip(new TeamMessage.Start(1), said));
        assertEquals(new TeamMessage.End(15), roundTrip(new TeamMessage.End(15), said));
        assertEquals(new TeamMessage.Unaware(6, true), roundTrip(new TeamMessage.Unaware(6, true), said));
        assertEquals(new TeamMessage.Unaware(2, false), roundTrip(new TeamMessage.Unaware(2, false), said));

        var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(5, -27.345, 17.891, 93.3, 27.49, -17.99), said);
        assertEquals(5, c.sender());
        assertEquals(-27.345, c.x(), X_TOL);
        assertEquals(17.891, c.y(), Y_TOL);
        assertEquals(93.3, c.thetaDeg(), ANGLE_TOL);
        assertEquals(27.49, c.ballX(), X_TOL);
        assertEquals(-17.99, c.ballY(), Y_TOL);

        var l = (TeamMessage.Location) roundTrip(new TeamMessage.Location(7, 3.3, -4.4, -170.2), said);
        assertEquals(3.3, l.x(), X_TOL);
        assertEquals(-4.4, l.y(), Y_TOL);
        assertEquals(-170.2, l.thetaDeg(), ANGLE_TOL);

        var b = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(4, 64.37, -33.0), said);
        assertEquals(64.37, b.distance(), D_TOL);
        assertEquals(-33.0, b.angleDeg(), ANGLE_TOL);

        var a = (TeamMessage.Actions) roundTrip(new TeamMessage.Actions(15, List.of(
                Action.walkTo(3, -20.5, 12.25, 45), Action.of(4, ActionId.ON_BALL))), said);
        assertEquals(15, a.remaining());
        assertEquals(2, a.actions().size());
        assertEquals(ActionId.WALK_TO_COORDINATE, a.actions().get(0).id());
        assertEquals(-20.5, a.actions().get(0).x(), X_TOL);
        assertEquals(12.25, a.actions().get(0).y(), Y_TOL);
        assertEquals(45, a.actions().get(0).thetaDeg(), ANGLE_TOL);
        assertEquals(Action.of(4, ActionId.ON_BALL), a.actions().get(1));

        var dirs = (TeamMessage.Actions) roundTrip(new TeamMessage.Actions(0, List.of(
                Action.towards(2, ActionId.WALK_TO_DIRECTION, 10), Action.towards(5, ActionId.DRIBBLE_TO_DIRECTION, -100),
                Action.of(6, ActionId.LOOK_STRAIGHT))), said);
        assertEquals(3, dirs.actions().size());
        assertEquals(-100, dirs.actions().get(1).thetaDeg(), ANGLE_TOL);
        assertEquals(Action.of(6, ActionId.LOOK_STRAIGHT), dirs.actions().get(2));
    }

    @Test
    void randomReportsRoundTripOverTheWholeField() {
        Random rnd = new Random(5);
        for (int i = 0; i < 2000; i++) {
            double x = (rnd.nextDouble() - 0.5) * 60, y = (rnd.nextDouble() - 0.5) * 40, th = (rnd.nextDouble() - 0.5) * 360;
            double bx = (rnd.nextDouble() - 0.5) * 60, by = (rnd.nextDouble() - 0.5) * 40;
            int u = 1 + rnd.nextInt(15);
            long said = rnd.nextInt(1 << 20);
            var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(u, x, y, th, bx, by), said);
            assertEquals(u, c.sender());
            assertEquals(x, c.x(), X_TOL);
            assertEquals(y, c.y(), Y_TOL);
            assertTrue(angleDiff(th, c.thetaDeg()) <= ANGLE_TOL, th + " vs " + c.thetaDeg());
            assertEquals(bx, c.ballX(), X_TOL);
            assertEquals(by, c.ballY(), Y_TOL);
        }
    }

    @Test
    void positionsOutsideTheCoveredRangeAreClamped() {
        var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(1, 100, -100, 0, -100, 100), 0);
        assertEquals(511 * 0.06, c.x(), 1e-9);
        assertEquals(-256 * 0.08, c.y(), 1e-9);
        assertEquals(-512 * 0.06, c.ballX(), 1e-9);
        assertEquals(255 * 0.08, c.ballY(), 1e-9);
        var b = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(1, 500, 0), 0);
        assertEquals(2047 * 0.04, b.distance(), 1e-9);
    }

    @Test
    void refusesWhatCannotBeSent() {
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Init(0), 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Init(16), 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Location(1, Double.NaN, 0, 0), 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Ball(1, -1, 0), 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(null, 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(16, List.of(Action.of(2, ActionId.ON_BALL))), 1));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(0, List.of()), 1));
        // two poses do not fit one frame (35 + 35 > 47 bits)
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(0, List.of(
                Action.walkTo(2, 0, 0, 0), Action.walkTo(3, 0, 0, 0))), 1));
        // six bare actions neither (6 x 8 > 47)
        List<Action> six = new ArrayList<>();
        for (int r = 2; r <= 7; r++) six.add(Action.of(r, ActionId.ON_BALL));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(0, six), 1));
        assertDoesNotThrow(() -> codec.encode(new TeamMessage.Actions(0, six.subList(0, 5)), 1));
    }

    @Test
    void packSplitsADispatchOnePosePerFrame() {
        List<Action> all = new ArrayList<>();
        for (int r = 2; r <= 7; r++) all.add(Action.walkTo(r, r, -r, 10 * r));
        List<TeamMessage.Actions> frames = MjTeamMessageCodec.pack(all);
        assertEquals(6, frames.size(), "7 v 7: six field players, one pose each, one frame each");
        for (int i = 0; i < frames.size(); i++) {
            assertEquals(frames.size() - 1 - i, frames.get(i).remaining());
            assertEquals(1, frames.get(i).actions().size());
            var back = (TeamMessage.Actions) roundTrip(frames.get(i), 100 + i);
            assertEquals(frames.get(i).actions().get(0).recipient(), back.actions().get(0).recipient());
            assertEquals(frames.get(i).actions().get(0).x(), back.actions().get(0).x(), X_TOL);
        }
        // poses and bare actions share frames: 3 poses + 3 bare actions -> 3 frames
        List<Action> mixed = new ArrayList<>();
        for (int r = 2; r <= 4; r++) mixed.add(Action.walkTo(r, 1, 1, 1));
        for (int r = 5; r <= 7; r++) mixed.add(Action.of(r, ActionId.TURN_TO_LOCALIZE));
        assertEquals(3, MjTeamMessageCodec.pack(mixed).size());
        // 11 v 11: ten poses, ten frames (SimSpark's codec packs them in five)
        List<Action> ten = new ArrayList<>();
        for (int r = 2; r <= 11; r++) ten.add(Action.walkTo(r, 0, 0, 0));
        assertEquals(10, MjTeamMessageCodec.pack(ten).size());
        assertEquals(5, TeamMessageCodec.pack(ten).size());
        assertThrows(IllegalArgumentException.class, () -> MjTeamMessageCodec.pack(List.of(Action.of(2, ActionId.ON_BALL),
                Action.of(2, ActionId.STAND_UP))));
    }

    @Test
    void rejectsBadFramesWithAReasonNeverAnException() {
        long said = 4242;
        byte[] frame = codec.encode(new TeamMessage.Location(3, 1, 2, 3), said);
        assertEquals(Rejection.EMPTY, codec.decode(null, said + 2).rejection());
        assertEquals(Rejection.EMPTY, codec.decode(new byte[0], said + 2).rejection());
        for (int n = 1; n < 10; n++) {
            assertEquals(Rejection.TOO_SHORT, codec.decode(Arrays.copyOf(frame, n), said + 2).rejection(), "truncated to " + n);
        }
        assertEquals(Rejection.TOO_LONG, codec.decode(Arrays.copyOf(frame, 11), said + 2).rejection());
        // another team's key (rcssservermj does not say who spoke): the check fails
        MjTeamMessageCodec theirs = new MjTeamMessageCodec(TeamKey.fromSecret("another-teams-key-0002"), CONFIG);
        assertEquals(Rejection.BAD_CHECK, codec.decode(theirs.encode(new TeamMessage.Location(3, 1, 2, 3), said), said + 2).rejection());
        // every single bit flipped: a bad check, the wrong time for the cycle bits
        for (int bit = 0; bit < 80; bit++) {
            byte[] f = frame.clone();
            f[bit >>> 3] ^= (byte) (0x80 >>> (bit & 7));
            Decoded d = codec.decode(f, said + 2);
            assertFalse(d.accepted(), "bit " + bit);
            if (bit == 27 || bit == 28) assertTrue(d.rejection() == Rejection.WRONG_TIME || d.rejection() == Rejection.BAD_CHECK);
            else assertEquals(Rejection.BAD_CHECK, d.rejection(), "bit " + bit);
        }
    }

    @Test
    void aReplayedFrameIsRejected() {
        long said = 9000;
        byte[] frame = codec.encode(new TeamMessage.Start(1), said);
        assertTrue(codec.decode(frame, said + 2).accepted());
        assertTrue(codec.decode(frame, said + 3).accepted());
        // an opponent hears it at said + 2 and says it again at once: it reaches us at said + 4 or later
        for (long heard = said + 4; heard < said + 40; heard++) {
            Decoded d = codec.decode(frame, heard);
            assertFalse(d.accepted(), "replay heard at +" + (heard - said));
            assertTrue(d.rejection() == Rejection.WRONG_TIME || d.rejection() == Rejection.BAD_CHECK, d.rejection().toString());
        }
        // too early (before the minimum latency) is as bad
        assertFalse(codec.decode(frame, said + 1).accepted());
        assertFalse(codec.decode(frame, said).accepted());
    }

    @Test
    void forgedFramesPassAboutOnceIn2To24() {
        Random rnd = new Random(3);
        byte[] f = new byte[10];
        int accepted = 0, n = 2_000_000;
        for (int i = 0; i < n; i++) {
            rnd.nextBytes(f);
            Decoded d = codec.decode(f, 5000);
            if (d.accepted()) accepted++;
            else assertNotNull(d.rejection());
        }
        // expected 2e6 x 1/2 (cycle bits) x 2^-24 x (share of canonical bodies) < 0.06
        assertTrue(accepted <= 1, accepted + " random frames accepted");
    }

    @Test
    void nonCanonicalBodiesAreMalformed() {
        // a valid check over a body with a stray padding bit, a zero sender, an action code no one knows
        long said = 77;
        byte[] init = codec.encode(new TeamMessage.Init(5), said);
        byte[] stray = init.clone();
        stray[9] |= 1;
        assertEquals(Rejection.MALFORMED, codec.decode(resign(stray, said), said + 2).rejection());
        byte[] zero = init.clone();
        zero[3] &= (byte) 0xf8; // type 0 and cycle bits stay; the sender's first 3 bits go
        zero[4] &= 0x7f;
        assertEquals(Rejection.MALFORMED, codec.decode(resign(zero, said), said + 2).rejection());
        byte[] actions = codec.encode(new TeamMessage.Actions(0, List.of(Action.of(2, ActionId.ON_BALL))), said);
        // the entry starts at body bit 9 (frame bit 33): recipient 4 bits, then the id's 4 bits at frame bits 37-40
        byte[] unknown = actions.clone();
        unknown[4] |= 0x07;
        unknown[5] |= (byte) 0x80; // id 15
        assertEquals(Rejection.MALFORMED, codec.decode(resign(unknown, said), said + 2).rejection());
    }

    /** The frame with its check recomputed (what a team-mate with another protocol version could send). */
    private static byte[] resign(byte[] frame, long said) {
        byte[] in = new byte[16];
        in[0] = 2;
        for (int i = 0; i < 8; i++) in[1 + i] = (byte) (said >>> (8 * i));
        System.arraycopy(frame, 3, in, 9, 7);
        int check = (int) (SipHash.hash(KEY.k0, KEY.k1, in, 16) & 0xffffff);
        byte[] out = frame.clone();
        out[0] = (byte) (check >>> 16);
        out[1] = (byte) (check >>> 8);
        out[2] = (byte) check;
        return out;
    }

    @Test
    void cycleOfGivesConsecutivePerceptionsConsecutiveNumbers() {
        // rcsssmj's clock as recorded: odd hundredths, where now / 0.02 sits on .5
        long first = MjTeamMessageCodec.cycleOf(138.83);
        for (int i = 1; i < 5000; i++) {
            double now = Math.round((138.83 + 0.02 * i) * 100) / 100.0;
            assertEquals(first + i, MjTeamMessageCodec.cycleOf(now), "at " + now);
        }
    }

    @Test
    void theTextFormIsTheFrameInBase64AndRejectsWhatIsNotBase64() {
        MjTeamMessageCodec codec = new MjTeamMessageCodec(KEY, ChannelConfig.MJ);
        SayCodec text = codec.text();
        TeamMessage m = new TeamMessage.Location(4, -10.2, 6.4, 90);
        String said = text.encode(m, 1001);
        assertEquals(16, said.length(), "10 bytes in padded base64: " + said);
        assertArrayEquals(codec.encode(m, 1001), java.util.Base64.getDecoder().decode(said));
        TeamMessageCodec.Decoded d = text.decode(said, 1003);
        assertEquals(m, d.message());
        assertEquals(1001, d.saidCycle());
        assertEquals(Rejection.FOREIGN_CHARACTER, text.decode("not base64!", 1003).rejection());
        assertEquals(Rejection.EMPTY, text.decode("", 1003).rejection());
        assertEquals(Rejection.TOO_LONG, text.decode(java.util.Base64.getEncoder().encodeToString(new byte[11]), 1003).rejection());
        assertEquals(Rejection.BAD_CHECK, new MjTeamMessageCodec(TeamKey.fromSecret("somebody-elses-key-000"), ChannelConfig.MJ).text()
                .decode(said, 1003).rejection(), "another team's frame");
        List<Action> six = List.of(Action.of(7, ActionId.ON_BALL), Action.walkTo(2, -20, 3, 0), Action.walkTo(3, -20, -3, 0),
                Action.walkTo(4, -15, 0, 0), Action.walkTo(5, -5, 6, 0), Action.walkTo(6, -5, -6, 0));
        assertEquals(MjTeamMessageCodec.pack(six), text.packActions(six));
        assertEquals(5, text.packActions(six).size(), "7 v 7's dispatch: five poses, the On Ball beside one of them");
    }
}

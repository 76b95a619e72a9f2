package phalanx.comm.team;

import org.junit.jupiter.api.Test;
import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.team.TeamMessageCodec.Decoded;
import phalanx.comm.team.TeamMessageCodec.Rejection;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.*;

class TeamMessageCodecTest {
    static final TeamKey KEY = TeamKey.fromSecret("match-key-for-tests-0001");
    static final ChannelConfig CONFIG = ChannelConfig.DEFAULT;
    // Requirement: positions to 5 cm or better, angles to 2° or better. The steps are 4 cm and
    // 1.41°, so a decoded value is within half a step of what was sent.
    static final double POS_TOL = 0.02 + 1e-9, ANGLE_TOL = 360.0 / 256 / 2 + 1e-9;

    private final TeamMessageCodec codec = new TeamMessageCodec(KEY, CONFIG);

    private TeamMessage roundTrip(TeamMessage m, long said) {
        String text = codec.encode(m, said);
        assertNull(EffectorMessage.sayProblem(text), text);
        for (char c : text.toCharArray()) assertTrue("'\"\\;".indexOf(c) < 0, "unsafe character in " + text);
        Decoded d = codec.decode(text, said + 2);
        assertTrue(d.accepted(), () -> m + " -> " + text + " rejected: " + d.rejection());
        assertEquals(said, d.saidCycle());
        return d.message();
    }

    static double angleDiff(double a, double b) {
        double d = Math.IEEEremainder(a - b, 360);
        return Math.abs(d);
    }

    @Test
    void everyTypeRoundTripsWithinTheResolution() {
        long said = 1234;
        assertEquals(new TeamMessage.Init(7), roundTrip(new TeamMessage.Init(7), said));
        assertEquals(new TeamMessage.Start(1), roundTrip(new TeamMessage.Start(1), said));
        assertEquals(new TeamMessage.End(1), roundTrip(new TeamMessage.End(1), said));
        assertEquals(new TeamMessage.Unaware(11, true), roundTrip(new TeamMessage.Unaware(11, true), said));
        assertEquals(new TeamMessage.Unaware(2, false), roundTrip(new TeamMessage.Unaware(2, false), said));

        var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(5, -12.345, 7.891, 93.3, 14.99, -9.99), said);
        assertEquals(5, c.sender());
        assertEquals(-12.345, c.x(), POS_TOL);
        assertEquals(7.891, c.y(), POS_TOL);
        assertEquals(93.3, c.thetaDeg(), ANGLE_TOL);
        assertEquals(14.99, c.ballX(), POS_TOL);
        assertEquals(-9.99, c.ballY(), POS_TOL);

        var l = (TeamMessage.Location) roundTrip(new TeamMessage.Location(9, 3.3, -4.4, -170.2), said);
        assertEquals(3.3, l.x(), POS_TOL);
        assertEquals(-4.4, l.y(), POS_TOL);
        assertEquals(-170.2, l.thetaDeg(), ANGLE_TOL);

        var b = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(4, 12.37, -33.0), said);
        assertEquals(12.37, b.distance(), POS_TOL);
        assertEquals(-33.0, b.angleDeg(), ANGLE_TOL);

        var a = (TeamMessage.Actions) roundTrip(new TeamMessage.Actions(3, List.of(
                Action.walkTo(2, -7.5, 3.25, 45), Action.of(6, ActionId.ON_BALL),
                Action.walkTo(10, 1.0, -1.0, -90))), said);
        assertEquals(3, a.remaining());
        assertEquals(3, a.actions().size());
        assertEquals(new Action(6, ActionId.ON_BALL, 0, 0, 0), a.actions().get(1));
        assertEquals(-7.5, a.actions().get(0).x(), POS_TOL);
        assertEquals(-90, a.actions().get(2).thetaDeg(), ANGLE_TOL);

        var dir = (TeamMessage.Actions) roundTrip(new TeamMessage.Actions(0, List.of(
                Action.towards(3, ActionId.DRIBBLE_TO_DIRECTION, 120))), said);
        assertEquals(ActionId.DRIBBLE_TO_DIRECTION, dir.actions().get(0).id());
        assertEquals(120, dir.actions().get(0).thetaDeg(), ANGLE_TOL);
    }

    @Test
    void messageLengthsAreTheDocumentedOnes() {
        assertEquals(7, codec.encode(new TeamMessage.Init(3), 0).length());
        assertEquals(7, codec.encode(new TeamMessage.Unaware(3, true), 0).length());
        assertEquals(10, codec.encode(new TeamMessage.Ball(3, 1, 1), 0).length());
        assertEquals(12, codec.encode(new TeamMessage.Location(3, 1, 1, 1), 0).length());
        assertEquals(15, codec.encode(new TeamMessage.Complete(3, 1, 1, 1, 1, 1), 0).length());
        // two poses and one bare action: 6 + 3 + 36 + 36 + 8 = 89 bits -> 15 body characters -> 20
        assertEquals(20, codec.encode(new TeamMessage.Actions(0, List.of(Action.walkTo(2, 1, 1, 1),
                Action.walkTo(3, 1, 1, 1), Action.of(4, ActionId.ON_BALL))), 0).length());
    }

    @Test
    void boundaryValuesClampOrWrapAsDocumented() {
        long said = 7;
        var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(15, 20.44, -20.48, 180, 100, -100), said);
        assertEquals(20.44, c.x(), 1e-9);
        assertEquals(-20.48, c.y(), 1e-9);
        assertEquals(-180, c.thetaDeg(), 1e-9); // 180 and -180 are one direction; decoded in [-180, 180)
        assertEquals(20.44, c.ballX(), 1e-9);   // clamped to the covered range
        assertEquals(-20.48, c.ballY(), 1e-9);
        var l = (TeamMessage.Location) roundTrip(new TeamMessage.Location(1, 0, 0, 359.9), said);
        assertEquals(0, l.thetaDeg(), ANGLE_TOL);
        var b = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(1, 0, 720 + 45), said);
        assertEquals(0, b.distance(), 1e-9);
        assertEquals(45, b.angleDeg(), ANGLE_TOL);
        var far = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(1, 99, 0), said);
        assertEquals(40.92, far.distance(), 1e-9);
        // the said cycle may be any long, including 0 and negatives
        assertEquals(new TeamMessage.Init(2), roundTrip(new TeamMessage.Init(2), 0));
        assertEquals(new TeamMessage.Init(2), roundTrip(new TeamMessage.Init(2), Long.MAX_VALUE - 5));
        assertEquals(new TeamMessage.Init(15), roundTrip(new TeamMessage.Init(15), -3));
    }

    @Test
    void randomValuesRoundTripWithinFiveCentimetresAndTwoDegrees() {
        Random r = new Random(42);
        for (int i = 0; i < 3000; i++) {
            long said = r.nextInt(1 << 20);
            int u = 1 + r.nextInt(15);
            double x = -15.5 + 31 * r.nextDouble(), y = -10.5 + 21 * r.nextDouble();
            double th = -540 + 1080 * r.nextDouble(), bx = -15.5 + 31 * r.nextDouble(), by = -10.5 + 21 * r.nextDouble();
            var c = (TeamMessage.Complete) roundTrip(new TeamMessage.Complete(u, x, y, th, bx, by), said);
            assertEquals(u, c.sender());
            assertEquals(x, c.x(), POS_TOL);
            assertEquals(y, c.y(), POS_TOL);
            assertTrue(angleDiff(th, c.thetaDeg()) <= ANGLE_TOL, th + " vs " + c.thetaDeg());
            assertEquals(bx, c.ballX(), POS_TOL);
            assertEquals(by, c.ballY(), POS_TOL);
            double d = 40 * r.nextDouble();
            var b = (TeamMessage.Ball) roundTrip(new TeamMessage.Ball(u, d, th), said);
            assertEquals(d, b.distance(), POS_TOL);
            assertTrue(angleDiff(th, b.angleDeg()) <= ANGLE_TOL);

            List<Action> actions = new ArrayList<>();
            ActionId[] ids = ActionId.values();
            for (int k = 2; k <= 11; k++) {
                ActionId id = ids[r.nextInt(ids.length)];
                actions.add(switch (id.params()) {
                    case NONE -> Action.of(k, id);
                    case DIRECTION -> Action.towards(k, id, th);
                    case POSE -> new Action(k, id, x, y, th);
                });
            }
            List<Action> back = new ArrayList<>();
            for (TeamMessage.Actions m : TeamMessageCodec.pack(actions)) back.addAll(((TeamMessage.Actions) roundTrip(m, said)).actions());
            back.sort(java.util.Comparator.comparingInt(Action::recipient));
            for (int k = 0; k < actions.size(); k++) {
                Action sent = actions.get(k), got = back.get(k);
                assertEquals(sent.recipient(), got.recipient());
                assertEquals(sent.id(), got.id());
                assertEquals(sent.x(), got.x(), POS_TOL);
                assertEquals(sent.y(), got.y(), POS_TOL);
                assertTrue(angleDiff(sent.thetaDeg(), got.thetaDeg()) <= ANGLE_TOL);
            }
        }
    }

    @Test
    void packingPutsSeveralPlayersInOneMessage() {
        // the usual dispatch: one on-ball player, nine walk-to-coordinate
        List<Action> actions = new ArrayList<>();
        actions.add(Action.of(9, ActionId.ON_BALL));
        for (int k = 2; k <= 11; k++) if (k != 9) actions.add(Action.walkTo(k, k, -k, 10 * k));
        List<TeamMessage.Actions> msgs = TeamMessageCodec.pack(actions);
        assertEquals(5, msgs.size()); // 9 x 36 bits at 81 a message: 2 poses each, the bare one rides along
        assertEquals(List.of(4, 3, 2, 1, 0), msgs.stream().map(TeamMessage.Actions::remaining).toList());
        assertEquals(10, msgs.stream().mapToInt(m -> m.actions().size()).sum());
        for (TeamMessage.Actions m : msgs) assertTrue(codec.encode(m, 0).length() <= 20);
        // ten bare actions (wait mode before a kick-off): 10 x 8 = 80 bits, one message
        List<Action> bare = new ArrayList<>();
        for (int k = 2; k <= 11; k++) bare.add(Action.of(k, ActionId.LOOK_STRAIGHT));
        assertEquals(1, TeamMessageCodec.pack(bare).size());
        assertEquals(0, TeamMessageCodec.pack(List.of()).size());
    }

    @Test
    void encoderRefusesWhatCannotBeSent() {
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Init(0), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Init(16), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Location(2, Double.NaN, 0, 0), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Ball(2, -1, 0), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Complete(2, 0, 0, Double.POSITIVE_INFINITY, 0, 0), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(0, List.of()), 0));
        assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(8, List.of(Action.of(2, ActionId.ON_BALL))), 0));
        IllegalArgumentException tooMany = assertThrows(IllegalArgumentException.class, () -> codec.encode(new TeamMessage.Actions(0, List.of(
                Action.walkTo(2, 0, 0, 0), Action.walkTo(3, 0, 0, 0), Action.walkTo(4, 0, 0, 0))), 0));
        assertTrue(tooMany.getMessage().contains("108 bits, one message holds 81"), tooMany.getMessage());
        assertThrows(IllegalArgumentException.class, () -> TeamMessageCodec.pack(List.of(Action.of(2, ActionId.ON_BALL), Action.of(2, ActionId.STAND_UP))));
        assertThrows(IllegalArgumentException.class, () -> Action.of(2, ActionId.WALK_TO_COORDINATE));
        assertThrows(IllegalArgumentException.class, () -> Action.walkTo(2, Double.NaN, 0, 0));
    }

    @Test
    void foreignTextIsRejectedWithItsReason() {
        // what the S4 probes said (recordings README)
        assertEquals(Rejection.TOO_SHORT, codec.decode("hello1", 100).rejection());
        assertEquals(Rejection.FOREIGN_CHARACTER, codec.decode("p1@c300", 100).rejection());
        assertEquals(Rejection.FOREIGN_CHARACTER, codec.decode("x=1.5;y=-2", 100).rejection());
        assertEquals(Rejection.TOO_LONG, codec.decode("abcdefghijklmnopqrstu", 100).rejection());
        Rejection r = codec.decode("abcdefghijklmnopqrst", 100).rejection();
        assertTrue(r == Rejection.WRONG_TIME || r == Rejection.BAD_CHECK, String.valueOf(r));
        assertEquals(Rejection.EMPTY, codec.decode("", 100).rejection());
        assertEquals(Rejection.EMPTY, codec.decode(null, 100).rejection());
        assertEquals(Rejection.FOREIGN_CHARACTER, codec.decode("AAAAA\u00e9AAA", 100).rejection());
    }

    @Test
    void randomTextNeverThrowsAndIsNeverAccepted() {
        Random r = new Random(7);
        String alphabet = TeamMessageCodec.ALPHABET;
        for (int i = 0; i < 200_000; i++) {
            int len = r.nextInt(24);
            StringBuilder sb = new StringBuilder(len);
            boolean ours = r.nextBoolean();
            for (int k = 0; k < len; k++) {
                sb.append(ours ? alphabet.charAt(r.nextInt(64)) : (char) r.nextInt(i % 2 == 0 ? 128 : 0x3000));
            }
            Decoded d = codec.decode(sb.toString(), r.nextInt(100000));
            assertFalse(d.accepted(), sb::toString);
        }
    }

    @Test
    void everySingleCharacterCorruptionIsRejected() {
        List<TeamMessage> msgs = List.of(new TeamMessage.Init(4), new TeamMessage.Complete(3, 1, 2, 3, 4, 5),
                new TeamMessage.Actions(1, List.of(Action.walkTo(2, 1, 1, 1), Action.walkTo(5, -3, 2, 90))));
        for (TeamMessage m : msgs) {
            String text = codec.encode(m, 500);
            for (int i = 0; i < text.length(); i++) {
                for (char c : TeamMessageCodec.ALPHABET.toCharArray()) {
                    if (c == text.charAt(i)) continue;
                    String bad = text.substring(0, i) + c + text.substring(i + 1);
                    assertFalse(codec.decode(bad, 502).accepted(), bad);
                }
            }
            // truncated and extended
            for (int n = 0; n < text.length(); n++) assertFalse(codec.decode(text.substring(0, n), 502).accepted());
            if (text.length() < 20) assertFalse(codec.decode(text + "A", 502).accepted());
        }
    }

    @Test
    void anotherKeyIsSpoofing() {
        TeamMessageCodec opponent = new TeamMessageCodec(TeamKey.fromSecret("a-guess-at-the-key-000"), CONFIG);
        String forged = opponent.encode(new TeamMessage.Actions(0, List.of(Action.of(5, ActionId.STAND_UP))), 300);
        assertEquals(Rejection.BAD_CHECK, codec.decode(forged, 302).rejection());
        assertTrue(opponent.decode(forged, 302).accepted());
    }

    @Test
    void acceptedOnlyTwoOrThreeCyclesAfterItWasSaid() {
        // A replay is heard at least 2 + 2 cycles after the original was said: rejected.
        String text = codec.encode(new TeamMessage.Start(1), 1000);
        for (long heard = 990; heard <= 1200; heard++) {
            Decoded d = codec.decode(text, heard);
            boolean inWindow = heard == 1002 || heard == 1003;
            assertEquals(inWindow, d.accepted(), "heard at " + heard + ": " + d.rejection());
            if (inWindow) assertEquals(1000, d.saidCycle());
            else assertTrue(d.rejection() == Rejection.WRONG_TIME || d.rejection() == Rejection.BAD_CHECK);
        }
        // the same content said at another cycle gives another text
        assertNotEquals(text, codec.encode(new TeamMessage.Start(1), 1004));
    }
}

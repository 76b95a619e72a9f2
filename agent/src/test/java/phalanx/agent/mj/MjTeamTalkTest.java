package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.team.Action;
import phalanx.comm.team.ActionId;
import phalanx.comm.team.ChannelConfig;
import phalanx.comm.team.MjTeamMessageCodec;
import phalanx.comm.team.TeamKey;
import phalanx.comm.team.TeamMessage;
import phalanx.comm.team.TeamMessageCodec.Rejection;
import phalanx.coordination.CoordinationConfig;
import phalanx.coordination.formation.Formation;
import phalanx.coordination.formation.StretchedFormation;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** The team channel on rcssservermj: the thesis's rounds over 10-byte frames, the goalkeeper's plan, the fallback. */
class MjTeamTalkTest {
    private static final TeamKey KEY = TeamKey.fromSecret("a-test-key-of-some-length");
    private static final MjField FIELD = MjField.SSIM;

    /** A perception as MjBehaviourTest.at makes it, with these messages heard. */
    private static MjPerception at(double t, String mode, Pose2 self, double ballDistance, List<MjPerception.Heard> heard) {
        MjPerception p = MjBehaviourTest.at(t, mode, self.x(), self.y(), self.thetaDeg(), ballDistance);
        return new MjPerception(p.time(), p.gameTime(), p.playMode(), p.teamLeft(), p.teamRight(), 0, 0, p.quat(), p.pos(), null, null,
                p.joints(), Map.of(), p.seen(), heard, 0);
    }

    /** One player of the seven: its world, its end of the channel, where it stands and how far ahead it sees the ball. */
    private record Member(int unum, MjWorld world, MjTeamTalk talk, Pose2 at, double ballAhead) {}

    /**
     * Seven players in PlayOn for {@code cycles} cycles on an air as rcsssmj makes it (docs/rcssservermj.md): said after
     * perception c, heard by every other player in perception c + 2. Player 7 stands 2 m behind the centre spot facing
     * the ball there; everyone else on its kick-off spot, the goalkeeper seeing the ball too, the others not.
     */
    private static List<Member> play(int cycles) {
        StretchedFormation kickOff = new StretchedFormation(FIELD, CoordinationConfig.THESIS.formation());
        List<Member> team = new ArrayList<>();
        for (int u = 1; u <= 7; u++) {
            MjWorld w = new MjWorld("Phalanx");
            Vector2 spot = kickOff.generate(Vector2.ZERO).position(kickOff.role(u));
            Pose2 at = u == 7 ? new Pose2(-2, 0, 0) : new Pose2(spot.x(), spot.y(), 0);
            team.add(new Member(u, w, new MjTeamTalk(KEY, "Phalanx", u, FIELD, w), at, u == 7 ? 2 : u == 1 ? -at.x() : 0));
        }
        Map<Integer, List<Said>> air = new HashMap<>();   // by the cycle they are heard in
        for (int c = 5000; c < 5000 + cycles; c++) {
            List<Said> said = new ArrayList<>();
            for (Member m : team) {
                List<MjPerception.Heard> heard = new ArrayList<>();
                for (Said s : air.getOrDefault(c, List.of())) if (s.speaker() != m.unum()) heard.add(new MjPerception.Heard(0, s.frame()));
                MjPerception p = at(c * 0.02, "PlayOn", m.at(), m.ballAhead(), heard);
                m.world().update(p);
                byte[] say = m.talk().step(p);
                if (say != null) said.add(new Said(m.unum(), say));
            }
            air.put(c + 2, said);
        }
        return team;
    }

    private record Said(int speaker, byte[] frame) {}

    @Test
    void theKeepersRoundsSendTheNearestToTheBallAndTheOthersToSpotsOnTheBigField() {
        List<Member> team = play(200);
        MjTeamTalk keeper = team.get(0).talk();
        assertTrue(keeper.channel().rounds() >= 3, keeper.channel().rounds() + " rounds in 200 cycles");
        assertEquals(6 * keeper.channel().rounds(), keeper.channel().reportsInRounds(), "every round heard all six field players");
        Vector2 ball = team.get(6).world().ball();
        assertEquals(0, ball.x(), 0.2, "player 7 sees the ball near the centre spot: " + ball);
        Formation spots = new StretchedFormation(FIELD, CoordinationConfig.THESIS.formation()).generate(ball);
        int walkers = 0, beyondSimSpark = 0;
        for (Member m : team.subList(1, 7)) {
            Action a = m.talk().order();
            assertNotNull(a, "player " + m.unum() + " has its order");
            assertTrue(m.talk().channel().actionsReceived() >= 2, "player " + m.unum() + " heard an order each round");
            if (m.unum() == 7) {
                assertEquals(ActionId.ON_BALL, a.id(), "player 7, 2 m from the ball, goes to it");
                continue;
            }
            assertEquals(ActionId.WALK_TO_COORDINATE, a.id(), "player " + m.unum());
            walkers++;
            Vector2 target = new Vector2(a.x(), a.y());
            // a support player's target is a spot of the stretched formation (to the frame's 6 and 8 cm grid); an
            // active player's one of the thesis's candidate positions 1-3 m from the ball (5.7)
            boolean formationSpot = spots.positions().values().stream().anyMatch(s -> s.distanceTo(target) < 0.06);
            boolean nearBall = target.distanceTo(ball) < 3.1;
            assertTrue(formationSpot || nearBall, "player " + m.unum() + "'s target " + target + " is neither a spot nor near the ball");
            if (Math.abs(target.x()) > FieldSpec.V066.halfLength()) beyondSimSpark++;
        }
        assertEquals(5, walkers);
        assertTrue(beyondSimSpark >= 1, "the defence's spots lie beyond SimSpark's 15 m: the plan is on the 55 x 36 m field");
    }

    @Test
    void aFieldPlayerTakesItsMatesPlacesFromTheirReports() {
        List<Member> team = play(200);
        MjTeamTalk three = team.get(2).talk();
        // each field player reports once a round; the others keep its place
        assertEquals(team.get(6).at().x(), three.mates().get(7).pose().x(), 0.06);
        assertFalse(three.nearestToBall(team.get(2).at(), team.get(6).world().ball(), team.get(2).world().time()),
                "player 7 is nearer the ball");
        assertFalse(three.mates().containsKey(1), "the goalkeeper does not report: it is the coordinator");
        assertTrue(three.accepted() >= 5 * 3, three.accepted() + " reports heard");
    }

    @Test
    void theRuleWithoutOrdersKeepsAwayFromTheBallOnlyWhileAMatesReportIsFresh() {
        MjWorld w = new MjWorld("Phalanx");
        MjTeamTalk three = new MjTeamTalk(KEY, "Phalanx", 3, FIELD, w);
        MjTeamMessageCodec mate = new MjTeamMessageCodec(KEY, ChannelConfig.MJ);
        Pose2 p3 = new Pose2(-5, 0, 0);
        Vector2 ball = new Vector2(2, 0);
        assertTrue(three.nearestToBall(p3, ball, 2.0), "alone: nearest");
        byte[] five = mate.encode(new TeamMessage.Complete(5, 1, 0, 0, 2, 0), 100);   // said after cycle 100 (2.00 s)
        MjPerception p = at(2.04, "PlayOn", p3, 0, List.of(new MjPerception.Heard(0, five)));
        w.update(p);
        three.step(p);
        assertEquals(1, three.accepted());
        assertFalse(three.nearestToBall(p3, ball, 2.1), "player 5 is 1 m from the ball, we are 7 m");
        assertFalse(three.mateAtBall(ball, 0.45, 1.0, 2.1), "1 m off is not at the ball (the double-touch rule's sign)");
        assertTrue(three.mateAtBall(new Vector2(1.3, 0), 0.45, 1.0, 2.1), "0.3 m off is");
        assertFalse(three.mateAtBall(new Vector2(1.3, 0), 0.45, 1.0, 3.1), "but not on a report 1.06 s old");
        assertFalse(three.mateAtBall(null, 0.45, 1.0, 2.1));
        assertTrue(three.nearestToBall(p3, ball, 2.04 + MjTeamTalk.FRESH_S + 0.1), "his report went stale");
        byte[] keeper = mate.encode(new TeamMessage.Complete(1, 1.5, 0, 0, 2, 0), 102);
        p = at(2.08, "PlayOn", p3, 0, List.of(new MjPerception.Heard(0, keeper)));
        w.update(p);
        three.step(p);
        assertTrue(three.nearestToBall(p3, ball, 2.04 + MjTeamTalk.FRESH_S + 0.1), "the goalkeeper never counts");
    }

    @Test
    void foreignAndBrokenMessagesAreRejectedAndChangeNothing() {
        MjWorld w = new MjWorld("Phalanx");
        MjTeamTalk three = new MjTeamTalk(KEY, "Phalanx", 3, FIELD, w);
        MjTeamMessageCodec them = new MjTeamMessageCodec(TeamKey.fromSecret("another-team-key-entirely"), ChannelConfig.MJ);
        byte[] foreignOrder = them.encode(new TeamMessage.Actions(0, List.of(Action.of(3, ActionId.ON_BALL))), 100);
        byte[] foreignReport = them.encode(new TeamMessage.Complete(5, 1, 0, 0, 2, 0), 100);
        byte[] random = {12, -3, 77, 0, 1, 99, -128, 127, 5, 6}, flipped = foreignReport.clone();
        flipped[9] ^= 1;
        MjPerception p = at(2.04, "PlayOn", new Pose2(-5, 0, 0), 0, List.of(new MjPerception.Heard(0, foreignOrder),
                new MjPerception.Heard(10, foreignReport), new MjPerception.Heard(20, random), new MjPerception.Heard(30, flipped),
                new MjPerception.Heard(40, new byte[] {1, 2, 3}), new MjPerception.Heard(50, new byte[11]), new MjPerception.Heard(60, new byte[0])));
        w.update(p);
        assertDoesNotThrow(() -> three.step(p));
        assertNull(three.order(), "no order from another team");
        assertEquals(0, three.accepted());
        assertTrue(three.mates().isEmpty());
        var c = three.channel();
        assertEquals(4, c.rejected(Rejection.BAD_CHECK) + c.rejected(Rejection.WRONG_TIME) + c.rejected(Rejection.MALFORMED),
                "the four 10-byte frames fail the check (or, for the random one, perhaps the cycle bits first)");
        assertEquals(1, c.rejected(Rejection.TOO_SHORT));
        assertEquals(1, c.rejected(Rejection.TOO_LONG));
        assertEquals(1, c.rejected(Rejection.EMPTY));
    }

    @Test
    void whatAT1Reports() {
        MjWorld w = new MjWorld("Phalanx");
        assertEquals(new TeamMessage.Unaware(4, false), MjTeamTalk.report(4, w), "nothing known yet");
        w.update(MjBehaviourTest.at(1, "PlayOn", -5, 2, 0, 0));
        assertEquals(new TeamMessage.Location(4, -5, 2, 0), MjTeamTalk.report(4, w), "no ball seen: where it is");
        w.update(MjBehaviourTest.at(1.02, "PlayOn", -5, 2, 0, 3));
        TeamMessage.Complete c = (TeamMessage.Complete) MjTeamTalk.report(4, w);
        assertEquals(w.ball().x(), c.ballX(), 1e-9);
        w.update(MjBehaviourTest.at(2.1, "PlayOn", -5, 2, 0, 0));
        assertInstanceOf(TeamMessage.Location.class, MjTeamTalk.report(4, w), "the ball last seen 1.08 s ago: not reported");
        w.update(MjBehaviourTest.at(2.12, "PlayOn", -5, 2, 0, 3));
        assertEquals(new TeamMessage.Unaware(4, false), MjTeamTalk.report(4, w, true),
                "barred by the double-touch rule: X, so that the coordinator gives On Ball to another");
    }
}

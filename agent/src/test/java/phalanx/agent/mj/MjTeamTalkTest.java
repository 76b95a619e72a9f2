package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.comm.team.TeamKey;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

class MjTeamTalkTest {
    private static final TeamKey KEY = TeamKey.fromSecret("a-test-key-of-some-length");

    private static MjPerception at(double t, List<MjPerception.Heard> heard) {
        return new MjPerception(t, 0, "PlayOn", "Phalanx", "Other", 0, 0, null, null, null, null, Map.of(), Map.of(),
                List.of(), heard, 0);
    }

    @Test
    void eachPlayerSaysInItsOwnSlotAndATeamMateNearerTheBallKeepsUsAway() {
        MjTeamTalk three = new MjTeamTalk(KEY, 3, 7), five = new MjTeamTalk(KEY, 5, 7);
        Vector2 ball = new Vector2(2, 0);
        Pose2 p3 = new Pose2(-5, 0, 0), p5 = new Pose2(1, 0, 0);
        // cycle 100 (time 2.00 s): 100 mod 7 = 2, player 3's slot; player 5 stays silent
        assertNotNull(three.say(at(2.00, List.of()), p3, ball));
        assertNull(five.say(at(2.00, List.of()), p5, ball));
        byte[] frame = five.say(at(2.04, List.of()), p5, ball);   // cycle 102: 102 mod 7 = 4, player 5's slot
        assertNotNull(frame);
        assertEquals(10, frame.length);
        assertTrue(three.nearestToBall(p3, ball, 2.0), "alone: nearest");
        three.hear(at(2.08, List.of(new MjPerception.Heard(0, frame))), 2.08);   // heard two cycles later
        assertEquals(1, three.accepted());
        assertEquals(1.0, three.mates().get(5).pose().x(), 0.06);
        assertFalse(three.nearestToBall(p3, ball, 2.1), "player 5 is 1 m from the ball, we are 7 m");
        assertTrue(three.nearestToBall(p3, ball, 2.1 + MjTeamTalk.FRESH_S + 0.1), "his report went stale");
    }

    @Test
    void anOpponentsOrABrokenFrameIsRejectedAndChangesNothing() {
        MjTeamTalk us = new MjTeamTalk(KEY, 3, 7), them = new MjTeamTalk(TeamKey.fromSecret("another-team-key-entirely"), 5, 7);
        byte[] foreign = them.say(at(2.04, List.of()), new Pose2(1, 0, 0), new Vector2(2, 0));
        us.hear(at(2.08, List.of(new MjPerception.Heard(0, foreign), new MjPerception.Heard(0, new byte[] {1, 2, 3}))), 2.08);
        assertEquals(0, us.accepted());
        assertEquals(2, us.rejected());
        assertTrue(us.nearestToBall(new Pose2(-5, 0, 0), new Vector2(2, 0), 2.1));
    }

    @Test
    void theGoalkeepersReportNeverSendsAFieldPlayerAway() {
        MjTeamTalk keeper = new MjTeamTalk(KEY, 1, 7), three = new MjTeamTalk(KEY, 3, 7);
        byte[] frame = keeper.say(at(1.96, List.of()), new Pose2(-25, 0, 0), new Vector2(-24, 0));   // cycle 98: 98 mod 7 = 0
        assertNotNull(frame);
        three.hear(at(2.00, List.of(new MjPerception.Heard(0, frame))), 2.00);
        assertEquals(1, three.accepted());
        assertTrue(three.nearestToBall(new Pose2(-10, 0, 0), new Vector2(-24, 0), 2.0));
    }
}

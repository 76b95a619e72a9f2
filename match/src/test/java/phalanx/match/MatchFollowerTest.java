package phalanx.match;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.comm.recording.Recordings;
import phalanx.match.MatchResult.Goal;
import phalanx.match.MatchResult.ModeChange;
import phalanx.match.MatchResult.RosterEvent;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

class MatchFollowerTest {

    private static String robot(int unum, String side) {
        return "(nd TRF (SLT 1 0 0 0 0 1 0 0 0 0 1 0 -3 1 0.38 1)(nd StaticMesh (setVisible 1) (load models/naobody0.obj) "
                + "(sSc 0.1 0.1 0.1)(resetMaterials matNum" + unum + " mat" + side + " matType0 naowhite)))";
    }

    private static String scene(String header, String... robots) {
        return "(" + header + ")(RSG 0 1)((nd TRF (SLT 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1))" + String.join("", robots) + ")";
    }

    @Test
    void realMonitorStreamGivesTeamRosterAndTimeline() throws Exception {
        // M1 (recordings README): one agent of team Probe, unum 1, left; trainer (kickOff Left) then (playMode PlayOn).
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        List<String> lines = Files.readAllLines(Recordings.dir().get().resolve("M1_monitor.txt"), StandardCharsets.ISO_8859_1);
        MatchFollower f = new MatchFollower();
        lines.forEach(f::accept);
        assertEquals("Probe", f.teamName(Side.LEFT));
        assertNull(f.teamName(Side.RIGHT));
        assertEquals(Set.of(1), f.present(Side.LEFT));
        assertEquals(List.of(2, 3, 4, 5, 6, 7, 8, 9, 10, 11), f.neverConnected(Side.LEFT, 11));
        assertTrue(f.disconnected(Side.LEFT).isEmpty());
        assertEquals(List.of(new RosterEvent(0, 1, "left", 1, true)), f.rosterEvents());
        assertEquals(List.of(new ModeChange(0, 1, "BeforeKickOff"), new ModeChange(0.04, 1, "KickOff_Left"),
                new ModeChange(1.04, 1, "PlayOn")), f.timeline());
        assertTrue(f.goals().isEmpty());
        assertEquals(300, f.halfTime(), 1e-9, "RuleHalfTime 300 in the first header");
        assertEquals(210, f.messages());
    }

    @Test
    void goalsHalvesAndDisconnectsFromAScriptedStream() {
        MatchFollower f = new MatchFollower();
        f.accept(scene("(RuleHalfTime 60)(play_modes BeforeKickOff KickOff_Left KickOff_Right PlayOn KickIn_Left KickIn_Right "
                + "corner_kick_left corner_kick_right goal_kick_left goal_kick_right offside_left offside_right GameOver Goal_Left "
                + "Goal_Right)(time 0)(team_left A)(team_right B)(half 1)(score_left 0)(score_right 0)(play_mode 0)",
                robot(1, "Left"), robot(2, "Left"), robot(1, "Right")));
        f.accept("((time 0.04)(play_mode 1))(RDS 0 1)()");
        f.accept("((time 12.5)(play_mode 3))(RDS 0 1)()");
        f.accept("((time 20.02)(score_right 1)(play_mode 14))(RDS 0 1)()");
        // robot 2 of A disconnects: the server sends a full scene without it
        f.accept(scene("(time 25.0)", robot(1, "Left"), robot(1, "Right")));
        f.accept("((time 60)(half 2)(play_mode 0))(RDS 0 1)()");
        f.accept("((time 75.5)(score_left 2)(play_mode 13))(RDS 0 1)()"); // two goals seen in one update
        f.accept("not a monitor message at all");
        f.accept("((time 120)(play_mode 12))(RDS 0 1)()");

        assertEquals(60, f.halfTime(), 1e-9);
        assertTrue(f.gameOver());
        assertEquals(2, f.state().scoreLeft());
        assertEquals(1, f.state().scoreRight());
        assertEquals(List.of(new Goal(20.02, 1, "right", "B", 0, 1), new Goal(75.5, 2, "left", "A", 1, 1),
                new Goal(75.5, 2, "left", "A", 2, 1)), f.goals());
        assertEquals(List.of(2), f.disconnected(Side.LEFT));
        assertEquals(new RosterEvent(25.0, 1, "left", 2, false), f.rosterEvents().get(f.rosterEvents().size() - 1));
        assertEquals(List.of(2, 3), f.neverConnected(Side.RIGHT, 3));
        List<String> modes = f.timeline().stream().map(ModeChange::mode).toList();
        assertEquals(List.of("BeforeKickOff", "KickOff_Left", "PlayOn", "Goal_Right", "BeforeKickOff", "Goal_Left", "GameOver"), modes);
        assertEquals(2, f.timeline().get(4).half(), "the second half's BeforeKickOff is recorded with half 2");
        assertEquals(PlayMode.GAME_OVER, f.state().playMode());
    }

    @Test
    void partialUpdatesDoNotChangeTheRoster() {
        MatchFollower f = new MatchFollower();
        f.accept(scene("(time 0)(play_mode 0)", robot(3, "Right")));
        f.accept("((time 1))(RDS 0 1)(" + robot(4, "Right") + ")"); // not a full scene: no roster in it
        assertEquals(Set.of(3), f.present(Side.RIGHT));
        assertTrue(SceneRoster.of("((time 1))(RDS 0 1)()").isEmpty());
        assertEquals(Set.of(new SceneRoster.Robot(Side.RIGHT, 3)), SceneRoster.of(scene("(time 0)", robot(3, "Right"))).orElseThrow());
    }
}

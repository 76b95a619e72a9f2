package phalanx.match;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Side;
import phalanx.comm.recording.Recordings;

import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

class GameStatsTest {
    private static final String MODES = "(play_modes BeforeKickOff KickOff_Left KickOff_Right PlayOn KickIn_Left KickIn_Right"
            + " corner_kick_left corner_kick_right goal_kick_left goal_kick_right offside_left offside_right GameOver"
            + " Goal_Left Goal_Right free_kick_left free_kick_right direct_free_kick_left direct_free_kick_right pass_left pass_right)";
    private static final int PLAY_ON = 3, FREE_KICK_LEFT = 15;

    /** A full scene: the ball and player 1 of the left team, upright or lying on its back. */
    private static String scene(double t, int mode, double bx, double by, double px, double py, boolean lying) {
        return scene(t, mode, 0, bx, by, px, py, lying);
    }

    private static String scene(double t, int mode, int scoreLeft, double bx, double by, double px, double py, boolean lying) {
        String torso = lying ? "1 0 0 0 0 0 1 0 0 -1 0 0" : "1 0 0 0 0 1 0 0 0 0 1 0";
        return String.format(Locale.ROOT, "(%s(time %.2f)(half 1)(score_left %d)(score_right 0)(play_mode %d))(RSG 0 1)("
                        + "(nd TRF (SLT 1 0 0 0 0 1 0 0 0 0 1 0 %.3f %.3f 0.042 1)(nd StaticMesh (load models/soccerball.obj)))"
                        + "(nd TRF (SLT %s %.3f %.3f 0.38 1)(nd TRF (nd StaticMesh (load models/naobody.obj) (resetMaterials matLeft matNum1)))))",
                MODES, t, scoreLeft, mode, bx, by, torso, px, py);
    }

    @Test
    void aKickTowardTheGoalAFallARelocationAndAFreeKickAreCountedForTheirTeam() {
        GameStats g = new GameStats(11);
        double t = 0;
        // 0.4 s at rest: the ball at (10, 0), our player 1 just behind it
        for (int i = 0; i <= 10; i++, t += 0.04) g.accept(scene(t, PLAY_ON, 10, 0, 9.8, 0, false));
        // kicked: 4 m/s along +x into the goal (0.16 m a picture), then at rest at x = 15.3
        double x = 10;
        while (x < 15.3) { x = Math.min(15.3, x + 0.16); g.accept(scene(t, PLAY_ON, x, 0, 9.8, 0, false)); t += 0.04; }
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(scene(t, PLAY_ON, 15.3, 0, 9.8, 0, false));
        // lies down for 1 s, then stands
        for (int i = 0; i < 25; i++, t += 0.04) g.accept(scene(t, PLAY_ON, 15.3, 0, 9.8, 0, true));
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(scene(t, PLAY_ON, 15.3, 0, 9.8, 0, false));
        // the ball put 5 m away in one picture (a placement, not a kick); the robot moved 3 m in one picture
        g.accept(scene(t, PLAY_ON, 10.3, 0, 9.8, 0, false)); t += 0.04;
        g.accept(scene(t, PLAY_ON, 10.3, 0, 6.8, 0, false)); t += 0.04;
        // a free kick for the left team
        g.accept(scene(t, FREE_KICK_LEFT, 10.3, 0, 6.8, 0, false)); t += 0.04;

        GameStats.TeamStats us = g.team(Side.LEFT), them = g.team(Side.RIGHT);
        assertEquals(1, us.kicks, g.line(Side.LEFT));
        GameStats.KickEvent k = g.kicks().get(0);
        assertEquals(10, k.x0(), 1e-9);
        assertEquals(15.3, k.x1(), 1e-9);
        assertEquals(5.3, k.length(), 1e-9);
        assertTrue(k.onGoal());
        assertEquals(1, us.shotsOnGoal);
        assertEquals(0, us.kicksOver8m);
        assertEquals(0, us.kicksUnder1_5m, "the kick went 5.3 m");
        assertEquals(1, us.falls);
        assertEquals(1.0, us.lyingS, 0.05);
        assertEquals(1, us.relocated);
        assertEquals(1, us.setPiece("free_kick"));
        assertEquals(0, them.kicks + them.falls + them.relocated);
        assertEquals(1.0, us.possessionS / g.playOnSeconds(), 1e-9, "nobody else on the field");
        assertEquals(1.0, us.opponentThirdS / g.playOnSeconds(), 1e-9, "the ball never left x > 5");
        assertEquals(us.opponentThirdS, them.ownThirdS, 1e-9);
        String line = g.line(Side.LEFT);
        assertTrue(line.startsWith("game-stats side=left ") && line.contains(" kicks=1 ") && line.contains(" falls=1 "), line);
        assertTrue(g.svg().startsWith("<svg") && g.svg().contains("fill-opacity"), "a heat map with cells");
    }

    @Test
    void aFreeKickRightAfterOurKickOffIsTheTakersFoulAndOneLaterIsNot() {
        final int KICK_OFF_LEFT = 1, FREE_KICK_RIGHT = 16;
        GameStats g = new GameStats(11);
        // as in g17f (docs/matches.md, sessions 12-13): PlayOn at 2.68 s, free_kick_right at 2.80 s
        g.accept(scene(0.04, KICK_OFF_LEFT, 0, 0, -0.3, 0, false));
        g.accept(scene(2.68, PLAY_ON, 0.05, 0, -0.3, 0, false));
        g.accept(scene(2.80, FREE_KICK_RIGHT, 0.05, 0, -0.3, 0, false));
        g.accept(scene(9.60, PLAY_ON, 0.05, 0, -0.3, 0, false));
        // the second kick-off is played on; the free kick 5 s later is another foul, not the taker's
        g.accept(scene(20.0, KICK_OFF_LEFT, 0, 0, -0.3, 0, false));
        g.accept(scene(22.0, PLAY_ON, 0.05, 0, -0.3, 0, false));
        g.accept(scene(27.0, FREE_KICK_RIGHT, 0.05, 0, -0.3, 0, false));
        GameStats.TeamStats us = g.team(Side.LEFT), them = g.team(Side.RIGHT);
        assertEquals(2, us.kickOffs);
        assertEquals(1, us.kickOffFouls, g.line(Side.LEFT));
        assertEquals(2, them.setPiece("free_kick"));
        assertEquals(0, them.kickOffs + them.kickOffFouls);
        assertTrue(g.line(Side.LEFT).contains(" kick_offs=2 kick_off_fouls=1 "), g.line(Side.LEFT));
    }

    @Test
    void aGoalIsListedWithItsShotOrAsWalkedIn() {
        final int GOAL_LEFT = 13;
        GameStats g = new GameStats(11);
        double t = 0;
        // kicked from (12, 0.5) at 4 m/s into the right goal; the score goes up when it is in (no right team: no keeper)
        for (int i = 0; i <= 10; i++, t += 0.04) g.accept(scene(t, PLAY_ON, 12, 0.5, 11.8, 0.5, false));
        double x = 12;
        while (x < 15.2) { x += 0.16; g.accept(scene(t, PLAY_ON, x, 0.5, 11.8, 0.5, false)); t += 0.04; }
        g.accept(scene(t, GOAL_LEFT, 1, 15.3, 0.5, 11.8, 0.5, false));
        assertEquals(1, g.goals().size());
        GameStats.Goal goal = g.goals().get(0);
        assertEquals(Side.LEFT, goal.scorer());
        assertNotNull(goal.shot(), "the kick that went in is the shot");
        assertEquals(12, goal.shot().x0(), 1e-9);
        assertNull(goal.shot().defence().keeper(), "the right team has no player 1 on the field");
        String line = GameStats.describe(goal);
        assertTrue(line.startsWith("goal t=") && line.contains(" left: shot t=0.40 from (12.00,0.50) 3.00 m to the line"), line);
        // the second goal: the ball walked in at 0.5 m/s (no kick), scored 20 s later
        t += 20;
        for (x = 14; x < 15.2; x += 0.02, t += 0.04) g.accept(scene(t, PLAY_ON, 1, x, 0, x - 0.2, 0, false));
        g.accept(scene(t, GOAL_LEFT, 2, 15.3, 0, 15.1, 0, false));
        assertEquals(2, g.goals().size());
        assertNull(g.goals().get(1).shot());
        assertTrue(GameStats.describe(g.goals().get(1)).contains("walked in"), GameStats.describe(g.goals().get(1)));
    }

    @Test
    void aLineThatIsNoMonitorMessageIsSkippedAndCounted() {
        GameStats g = new GameStats(11);
        g.accept(scene(0, PLAY_ON, 0, 0, 1, 1, false));
        g.accept("((time 1.0)(RSG 0 1)((nd TRF (SLT 1 0");    // truncated
        g.accept(scene(0.04, PLAY_ON, 0, 0, 1, 1, false));
        assertEquals(3, g.messages());
        assertEquals(1, g.unreadable());
    }

    /** On the monitor stream recorded from the real server (M1, recordings README; skips without it). */
    @Test
    void theRecordedTrainerRunHasOnlyPlacementsAndOneMove() throws Exception {
        assumeTrue(Recordings.dir().isPresent(), Recordings.missingMessage());
        GameStats g = GameStats.read(Recordings.dir().get().resolve("M1_monitor.txt"), 11);
        assertEquals(0, g.unreadable());
        GameStats.TeamStats us = g.team(Side.LEFT);
        // M1_trainer.txt: the ball is only ever placed ((ball (pos ..)) three times, (dropBall)), never kicked
        assertEquals(0, us.kicks + g.team(Side.RIGHT).kicks, g.line(Side.LEFT));
        // ... and the robot is moved 2.2 m by (agent ... (move -2 2 0.4 0)) at 7.62 s, in PlayOn
        assertEquals(1, us.relocated);
        assertEquals(1.0, us.possessionS / g.playOnSeconds(), 1e-9, "the only robot on the field");
        assertTrue(g.playOnSeconds() > 3 && g.playOnSeconds() < 6, "PlayOn from 4.62 s to the end: " + g.playOnSeconds());
    }

    @Test
    void aTrackedRobotIsPrintedEveryStepWithTheBall(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        // Player 1 walks from x = 0 to x = 2 in 2 s (0.04 s a picture), then lies; the ball stays at (5, 1).
        StringBuilder log = new StringBuilder();
        double t = 0;
        for (int i = 0; i <= 50; i++, t += 0.04) log.append(scene(t, PLAY_ON, 5, 1, i * 0.04, 0, false)).append('\n');
        for (int i = 0; i < 25; i++, t += 0.04) log.append(scene(t, PLAY_ON, 5, 1, 2, 0, true)).append('\n');
        Path file = dir.resolve("monitor.log");
        java.nio.file.Files.writeString(file, log);
        GameStats.Tracked me = GameStats.Tracked.parse("left:1"), them = GameStats.Tracked.parse("right:4");
        java.util.List<String> lines = new java.util.ArrayList<>();
        double[] next = {0};
        GameStats.read(file, 11, g -> {
            if (g.state().time() < next[0]) return;
            lines.add(me.line(g.state().time(), g));
            lines.add(them.line(g.state().time(), g));
            next[0] += 1;
        });
        assertEquals(8, lines.size(), lines.toString());
        assertEquals("track t=0.00 left 1 (0.00,0.00) up tilt +0 fwd +0 right ball (5.00,1.00)", lines.get(0));
        assertEquals("track t=3.00 left 1 (2.00,0.00) lying tilt -90 fwd +0 right ball (5.00,1.00)", lines.get(6), "on its back: the torso tilted 90 deg backward");
        assertEquals("track t=0.00 right 4 not on the field ball (5.00,1.00)", lines.get(1));
        assertEquals("track t=1.00 left 1 (1.00,0.00) up tilt +0 fwd +0 right ball (5.00,1.00)", lines.get(2));
        assertEquals("track t=2.00 left 1 (2.00,0.00) up tilt +0 fwd +0 right ball (5.00,1.00)", lines.get(4));
        assertThrows(IllegalArgumentException.class, () -> GameStats.Tracked.parse("middle:1"));
        assertThrows(IllegalArgumentException.class, () -> GameStats.Tracked.parse("left:12"));
        assertThrows(IllegalArgumentException.class, () -> GameStats.Tracked.parse("left"));
    }

    @Test
    void theCommandRefusesAMissingLog() {
        assertThrows(java.nio.file.NoSuchFileException.class, () -> GameStats.read(Path.of("/nonexistent/monitor.log.gz"), 11));
    }

    /** A scene of robots given as {side (0 left, 1 right), unum, x, y, z, lying (1/0)} each, and the ball. */
    private static String robots(double t, int mode, double bx, double by, double[]... robots) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "(%s(time %.2f)(half 1)(score_left 0)(score_right 0)(play_mode %d))(RSG 0 1)("
                + "(nd TRF (SLT 1 0 0 0 0 1 0 0 0 0 1 0 %.3f %.3f 0.042 1)(nd StaticMesh (load models/soccerball.obj)))", MODES, t, mode, bx, by));
        for (double[] r : robots) {
            String torso = r[5] > 0 ? "1 0 0 0 0 0 1 0 0 -1 0 0" : "1 0 0 0 0 1 0 0 0 0 1 0";
            b.append(String.format(Locale.ROOT, "(nd TRF (SLT %s %.3f %.3f %.3f 1)(nd TRF (nd StaticMesh (load models/naobody.obj) (resetMaterials %s matNum%d))))",
                    torso, r[2], r[3], r[4], r[0] == 0 ? "matLeft" : "matRight", (int) r[1]));
        }
        return b.append(")").toString();
    }

    @Test
    void aStillBallWithAPlayerOfEachTeamAtItIsAContestWonByTheTeamThatKicksItNext() {
        GameStats g = new GameStats(11);
        double t = 0;
        // 0.6 s: left 2 and right 5 at a still ball, too short for a contest; then right 5 lies down for 1 s: none either
        for (int i = 0; i < 15; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 0, 0, new double[] {0, 2, -0.5, 0, 0.38, 0}, new double[] {1, 5, 0.4, 0, 0.38, 0}));
        for (int i = 0; i < 25; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 0, 0, new double[] {0, 2, -0.5, 0, 0.38, 0}, new double[] {1, 5, 0.4, 0, 0.38, 1}));
        assertEquals(0, g.contests(), "0.6 s, then one of them lying");
        // 1.6 s with both up at the still ball: a contest ...
        for (int i = 0; i < 40; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 0, 0, new double[] {0, 2, -0.5, 0, 0.38, 0}, new double[] {1, 5, 0.4, 0, 0.38, 0}));
        // ... that right 5 (the nearer) ends with a kick toward -x at 4 m/s
        double x = 0;
        for (int i = 0; i < 20; i++, t += 0.04) { x -= 0.16; g.accept(robots(t, PLAY_ON, x, 0, new double[] {0, 2, -0.5, 0, 0.38, 0}, new double[] {1, 5, 0.4, 0, 0.38, 0})); }
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(robots(t, PLAY_ON, x, 0, new double[] {0, 2, -0.5, 0, 0.38, 0}, new double[] {1, 5, 0.4, 0, 0.38, 0}));
        assertEquals(1, g.contests(), g.line(Side.LEFT));
        assertEquals(1.6, g.contestSeconds(), 0.05);
        assertEquals(1, g.team(Side.RIGHT).contestsWon);
        assertEquals(0, g.team(Side.LEFT).contestsWon);
        assertTrue(g.line(Side.RIGHT).contains(" contests=1 contests_won=1 contest_s=1.6 "), g.line(Side.RIGHT));
        assertTrue(g.line(Side.LEFT).contains(" contests=1 contests_won=0 "), g.line(Side.LEFT));
        // Another contest ended by a free kick: nobody wins it, whoever kicks after the set piece.
        for (int i = 0; i < 40; i++, t += 0.04) g.accept(robots(t, PLAY_ON, x, 0, new double[] {0, 2, x - 0.3, 0, 0.38, 0}, new double[] {1, 5, x + 0.4, 0, 0.38, 0}));
        g.accept(robots(t, FREE_KICK_LEFT, x, 0, new double[] {0, 2, x - 0.3, 0, 0.38, 0}, new double[] {1, 5, x + 0.4, 0, 0.38, 0}));
        t += 0.04;
        double from = x;
        for (int i = 0; i < 10; i++, t += 0.04) { x += 0.16; g.accept(robots(t, PLAY_ON, x, 0, new double[] {0, 2, from - 0.3, 0, 0.38, 0})); }
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(robots(t, PLAY_ON, x, 0, new double[] {0, 2, from - 0.3, 0, 0.38, 0}));
        assertEquals(1, g.team(Side.LEFT).kicks, "the left team took the free kick");
        assertEquals(2, g.contests());
        assertEquals(0, g.team(Side.LEFT).contestsWon, "the free kick, not the contest, gave the left team the ball");
    }

    @Test
    void aPlayerHeldUpByTheRefereeIsAFoulOfTheKindThePictureBeforeShows() {
        GameStats g = new GameStats(11);
        double t = 0;
        // left 2 walks into right 5, who stands 0.3 m nearer the ball at (4, 0)
        for (int i = 0; i < 10; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 4, 0, new double[] {0, 2, 3.0, 0, 0.38, 0},
                new double[] {1, 5, 3.3, 0, 0.38, 0}, new double[] {0, 7, -6, 5, 0.38, 1}));
        // the referee holds left 2 up for 0.5 s (z 1.0 and more) and left 7, lying since, too
        for (int i = 0; i < 13; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 4, 0, new double[] {0, 2, 3.0, 0, 1.0 + 0.02 * i, 0},
                new double[] {1, 5, 3.3, 0, 0.38, 0}, new double[] {0, 7, -6, 5, 1.0 + 0.02 * i, 1}));
        // ... then puts them beside the field
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 4, 0, new double[] {0, 2, -3, -10.5, 0.4, 0},
                new double[] {1, 5, 3.3, 0, 0.38, 0}, new double[] {0, 7, -0.6, -10.5, 0.4, 0}));
        GameStats.TeamStats us = g.team(Side.LEFT);
        assertEquals(1, us.fouls(GameStats.Foul.Kind.CONTACT), g.line(Side.LEFT));
        assertEquals(1, us.fouls(GameStats.Foul.Kind.INCAPABLE), g.line(Side.LEFT));
        assertEquals(2, us.fouls.values().stream().mapToInt(Integer::intValue).sum());
        assertTrue(g.team(Side.RIGHT).fouls.isEmpty());
        assertEquals(2, us.relocated, "each was moved off once");
        assertEquals(0, us.falls, "held and put down is no fall");
        GameStats.Foul charge = g.fouls().stream().filter(f -> f.unum() == 2).findFirst().orElseThrow();
        assertEquals(GameStats.Foul.Kind.CONTACT, charge.kind());
        assertEquals(1.0, charge.ballDistance(), 1e-9);
        assertEquals(0.3, charge.nearestOpponent(), 1e-9);
        assertTrue(charge.opponentNearerBall());
        assertEquals("foul t=0.36 left 2 contact at (3.00,0.00): ball 1.00 m, nearest opponent 0.30 m (nearer the ball)",
                GameStats.describe(charge));
        assertTrue(g.line(Side.LEFT).endsWith(" fouls_charging=0 fouls_touching=0 fouls_contact=1 fouls_incapable=1"
                + " fouls_illegal_defence=0 fouls_other=0 self_collisions=0"), g.line(Side.LEFT));
    }

    @Test
    void aFourthFieldPlayerInsideHisOwnAreaHeldUpIsIllegalDefence() {
        GameStats g = new GameStats(11);
        double t = 0;
        double[][] inside = new double[4][];
        for (int u = 2; u <= 5; u++) inside[u - 2] = new double[] {0, u, -14.0, -1.5 + u * 0.5, 0.38, 0};
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(robots(t, PLAY_ON, -13, 0, inside));
        inside[3] = new double[] {0, 5, -14.0, 1.0, 1.0, 0};
        g.accept(robots(t, PLAY_ON, -13, 0, inside));
        assertEquals(1, g.team(Side.LEFT).fouls(GameStats.Foul.Kind.ILLEGAL_DEFENCE), g.line(Side.LEFT));
        assertEquals(0, g.team(Side.LEFT).fouls(GameStats.Foul.Kind.CONTACT));
    }

    @Test
    void theServersNameForAFoulWinsAndSelfCollisionsAreCountedWithoutAMove() {
        GameStats g = new GameStats(11);
        double t = 0;
        double[] me = {0, 2, 3.0, 0, 0.38, 0}, him = {1, 5, 3.3, 0, 0.38, 0};
        for (int i = 0; i < 5; i++, t += 0.04) g.accept(robots(t, PLAY_ON, 4, 0, me, him));
        // SoccerRuleItem: (foul index type team unum); 7 = FT_SelfCollision of right 5 (not moved), 6 = FT_Charging of left 2
        g.accept(robots(t, PLAY_ON, 4, 0, me, him).replace("(play_mode 3)", "(play_mode 3)(foul 1 7 2 5)")); t += 0.04;
        g.accept(robots(t, PLAY_ON, 4, 0, me, him).replace("(play_mode 3)", "(play_mode 3)(foul 2 6 1 2)(foul 3 6 1 2)")); t += 0.04;
        g.accept(robots(t, PLAY_ON, 4, 0, new double[] {0, 2, 3.0, 0, 1.01, 0}, him).replace("(play_mode 3)", "(play_mode 3)(foul 4 6 1 2)"));
        t += 0.04;
        g.accept(robots(t, PLAY_ON, 4, 0, new double[] {0, 2, 3.0, 0, 1.02, 0}, him).replace("(play_mode 3)", "(play_mode 3)(foul x y)"));
        assertEquals(1, g.team(Side.LEFT).fouls(GameStats.Foul.Kind.CHARGING), g.line(Side.LEFT));
        assertEquals(0, g.team(Side.LEFT).fouls(GameStats.Foul.Kind.CONTACT));
        assertEquals(1, g.team(Side.RIGHT).selfCollisions, g.line(Side.RIGHT));
        assertTrue(g.team(Side.RIGHT).fouls.isEmpty(), "a self collision moves no one");
        assertEquals(0, g.unreadable(), "a foul record of another format is left alone");
        assertTrue(GameStats.describe(g.fouls().get(0)).contains(" left 2 charging at (3.00,0.00)"), GameStats.describe(g.fouls().get(0)));
    }
}

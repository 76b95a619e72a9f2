package phalanx.agent.action;

import org.junit.jupiter.api.Test;
import phalanx.agent.AgentConfig;
import phalanx.agent.act.Locomotion;
import phalanx.agent.decide.Action;
import phalanx.agent.decide.Decision;
import phalanx.agent.decide.Situation;
import phalanx.agent.goalkeeper.Goalkeeper;
import phalanx.agent.goalkeeper.GoalkeeperBehaviour;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.team.ActionId;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import static org.junit.jupiter.api.Assertions.*;

/** No belief, no self, NaN everywhere, a ball never seen: every action gives a safe decision, never an exception. */
class BadInputTest {
    private static final AgentConfig C = AgentConfig.DEFAULT;

    private static Map<String, Supplier<Action>> actions() {
        Map<String, Supplier<Action>> m = new LinkedHashMap<>();
        m.put("LookStraight", LookStraight::new);
        m.put("PanHead", () -> new PanHead(C));
        m.put("Scan", () -> new Scan(C));
        m.put("TrackBall", () -> TrackObject.ball(C));
        m.put("TrackPoint", () -> TrackObject.point(C, new Vector2(1, 1), 0));
        m.put("TrackMovingObject", () -> new TrackMovingObject(C));
        m.put("FindOpponentGoal", () -> new FindOpponentGoal(C));
        m.put("LookForBall", () -> new LookForBall(C));
        m.put("TurnToBall", () -> new TurnToBall(C));
        m.put("TurnToLocalize", () -> new TurnToLocalize(C));
        m.put("StandUp", () -> new StandUp(C));
        m.put("PrepareForKick", () -> new PrepareForKick(C));
        m.put("KickBall", () -> new KickBall(C));
        m.put("WalkToBall", () -> new WalkToBall(C));
        m.put("OnBall", () -> new OnBall(C));
        m.put("WalkToCoordinate", () -> new WalkToCoordinate(C, 3, 2, 45));
        m.put("WalkToDirection", () -> new WalkToDirection(C, 30));
        m.put("Dribble", () -> new DribbleBallToDirection(C, 30));
        m.put("Goalkeeper", () -> new Goalkeeper(C));
        m.put("GoalkeeperBehaviour", () -> { var g = new GoalkeeperBehaviour(C); return g::decide; });
        m.put("FieldPlayerBehaviour(OnBall order)", () -> {
            var f = new FieldPlayerBehaviour(C);
            f.order(phalanx.comm.team.Action.of(5, ActionId.ON_BALL));
            return s -> f.decide(s, false, new Vector2(-5, 0));
        });
        m.put("FieldPlayerBehaviour(quiet)", () -> {
            var f = new FieldPlayerBehaviour(C);
            return s -> f.decide(s, true, new Vector2(Double.NaN, 0));
        });
        return m;
    }

    private static Map<String, Situation> badSituations() {
        Map<String, Situation> m = new LinkedHashMap<>();
        m.put("null belief", new Situation(10, 500, PlayMode.PLAY_ON, 10, null, FieldSpec.V066, JointAngles.none(),
                Situation.MotionStatus.IDLE));
        m.put("no self, ball never seen", World.lost().situation());
        World nanBall = World.at(0, 0, 0);
        nanBall.ballRel = new Vector2(Double.NaN, 1);
        nanBall.ballGlobal = new Vector2(Double.NaN, Double.NaN);
        nanBall.ballAge = 0;
        nanBall.ballVelocity = new Vector2(Double.NaN, 0);
        m.put("NaN ball", nanBall.situation());
        World nanSelf = World.at(0, 0, 0).ballRel(0.17, -0.055);
        nanSelf.self = new Pose2(Double.NaN, 0, Double.NaN);
        m.put("NaN self", nanSelf.situation());
        World nanAge = World.at(0, 0, 0).ballRel(1, 0);
        nanAge.ballAge = Double.NaN;
        nanAge.selfAge = Double.NaN;
        nanAge.confidence = Double.NaN;
        m.put("NaN ages", nanAge.situation());
        World nanTime = World.at(-14.5, 0, 0).ballAt(-13.5, 0.4).ballVelocity(-3, 0.2).time(Double.NaN);
        m.put("NaN time", nanTime.situation());
        m.put("null field, joints and motion", new Situation(10, 500, PlayMode.PLAY_ON, 10,
                World.at(0, 0, 0).ballRel(0.2, 0).belief(), null, null, null));
        m.put("null player lists and fall", new Situation(10, 500, PlayMode.PLAY_ON, 10,
                new WorldBelief(10, null, 0, new Pose2(0, 0, 0), 1, 0, new Vector2(0.2, 0), new Vector2(0.2, 0), 0,
                        new Vector2(-1, 0), null, null, null, false), FieldSpec.V066, JointAngles.none(), null));
        return m;
    }

    @Test
    void everyActionGivesASafeDecisionOnBadInput() {
        List<String> failures = new ArrayList<>();
        for (var a : actions().entrySet()) {
            for (var s : badSituations().entrySet()) {
                Action action = a.getValue().get();
                try {
                    for (int i = 0; i < 3; i++) {
                        Decision d = action.decide(s.getValue());
                        assertNotNull(d);
                        assertTrue(Double.isFinite(d.head().yawDeg()) && Double.isFinite(d.head().pitchDeg()), "head " + d.head());
                        assertNotNull(Locomotion.request(d.move()), "the motion request accepts " + d.move());
                        action.done(s.getValue());
                    }
                } catch (RuntimeException | AssertionError e) {
                    failures.add(a.getKey() + " with " + s.getKey() + ": " + e);
                }
            }
        }
        assertTrue(failures.isEmpty(), String.join("\n", failures));
    }
}

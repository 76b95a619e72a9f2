package phalanx.coordination.active;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.OnBallConfig;
import phalanx.coordination.beliefs.PlayerBelief;
import phalanx.coordination.beliefs.ReportType;
import phalanx.model.field.Vector2;

class OnBallChooserTest {
    private static final Vector2 BALL = new Vector2(0, 0), GOAL = new Vector2(15, 0);
    private static final OnBallConfig C = OnBallConfig.THESIS;

    private static PlayerBelief at(int id, double x, double y) {
        Vector2 p = new Vector2(x, y);
        return new PlayerBelief(id, ReportType.L, p, 0, p.distanceTo(BALL), false);
    }

    @Test
    void angleOffIsTheTurnAroundTheBall() {
        assertEquals(0, OnBallChooser.angleOff(new Vector2(-1, 0), BALL, GOAL), 1e-9);
        assertEquals(90, OnBallChooser.angleOff(new Vector2(0, -1), BALL, GOAL), 1e-9);
        assertEquals(180, OnBallChooser.angleOff(new Vector2(1, 0), BALL, GOAL), 1e-9);
    }

    @Test
    void valueIsDistancePlusAHundredthOfADegree() {
        // 2 m in front of the ball, facing the wrong way: 2 + 0.01·180 = 3.8.
        assertEquals(3.8, OnBallChooser.value(at(3, 2, 0), BALL, GOAL, C, 0), 1e-9);
        assertEquals(2.8, OnBallChooser.value(at(3, 2, 0), BALL, GOAL, C, 3), 1e-9);
    }

    @Test
    void angleBreaksNearTies() {
        // 1.0 m in front (value 2.8) loses to 1.5 m behind (value 1.5).
        assertEquals(5, OnBallChooser.choose(List.of(at(4, 1, 0), at(5, -1.5, 0)), BALL, GOAL, C, 0));
    }

    @Test
    void previousOnBallPlayerKeepsTheBallWithinTheHysteresis() {
        List<PlayerBelief> team = List.of(at(2, -1.0, 0), at(3, -1.9, 0));
        assertEquals(2, OnBallChooser.choose(team, BALL, GOAL, C, 0));
        assertEquals(3, OnBallChooser.choose(team, BALL, GOAL, C, 3), "0.9 m farther, kept");
        List<PlayerBelief> farther = List.of(at(2, -1.0, 0), at(3, -2.1, 0));
        assertEquals(2, OnBallChooser.choose(farther, BALL, GOAL, C, 3), "1.1 m farther, handed over");
    }
}

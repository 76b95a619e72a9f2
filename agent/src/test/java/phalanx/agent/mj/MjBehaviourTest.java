package phalanx.agent.mj;

import org.junit.jupiter.api.Test;
import phalanx.comm.mj.MjPerception;
import phalanx.coordination.formation.Role;
import phalanx.model.field.MjField;
import phalanx.model.field.Pose2;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

class MjBehaviourTest {
    private static final double S = Math.sqrt(0.5);
    private static final Map<String, double[]> HEAD = Map.of("q_hj1", new double[] {0, 0}, "q_hj2", new double[] {0, 0});

    /** A perception of an upright T1 at (x, y) facing yaw (world), optionally seeing the ball straight ahead at d. */
    private static MjPerception at(double t, String mode, double x, double y, double yawDeg, double ballDistance) {
        double h = Math.toRadians(yawDeg) / 2;
        List<MjPerception.Seen> seen = ballDistance > 0 ? List.of(new MjPerception.Seen("B", ballDistance, 0, 0)) : List.of();
        return new MjPerception(t, 0, mode, "Phalanx", "Other", 0, 0, new double[] {Math.cos(h), 0, 0, Math.sin(h)},
                new double[] {x, y, 0.67}, null, null, HEAD, Map.of(), seen, List.of(), 0);
    }

    @Test
    void beamsToItsKickOffSpotOnceASecondUntilThere() {
        MjBehaviour b = new MjBehaviour(MjField.SSIM, 3, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(10, "BeforeKickOff", -3, 21, -90, 0));
        Pose2 spot = b.kickOffSpot();
        assertEquals(spot, b.decide(w).beam());
        w.update(at(10.02, "BeforeKickOff", -3, 21, -90, 0));
        assertNull(b.decide(w).beam(), "not again within a second");
        w.update(at(11.1, "BeforeKickOff", -3, 21, -90, 0));
        assertEquals(spot, b.decide(w).beam(), "refused or not yet there: again");
        w.update(at(12.2, "BeforeKickOff", spot.x() + 0.05, spot.y(), 0, 0));
        assertSame(MjBehaviour.Intent.STAND, b.decide(w), "there: stand");
    }

    @Test
    void inPlayOnTheForwardWalksAtTheBallAndTurnsFirstWhenItIsBehind() {
        MjBehaviour fc = new MjBehaviour(MjField.SSIM, 7, MjBehaviour.Config.DEFAULT);
        assertEquals(Role.FC, fc.role());
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -5, 0, 0, 4));            // ball 4 m ahead
        MjBehaviour.Intent i = fc.decide(w);
        assertTrue(i.vx() > 0 && Math.abs(i.turnDegPerS()) < 5, "walks straight at it: " + i);
        w.update(at(1.1, "PlayOn", -5, 0, 180, 0));        // now facing away; ball still remembered at (-0.9.., 0)
        i = fc.decide(w);
        assertEquals(0, i.vx(), 1e-9, "turns in place first: " + i);
        assertEquals(MjBehaviour.Config.DEFAULT.maxTurn(), Math.abs(i.turnDegPerS()), 1e-9);
    }

    @Test
    void aDefenderWithoutABallInSightTurnsToLookForIt() {
        MjBehaviour dc = new MjBehaviour(MjField.SSIM, 3, MjBehaviour.Config.DEFAULT);
        MjWorld w = new MjWorld("Phalanx");
        w.update(at(1, "PlayOn", -20, 0, 0, 0));
        assertNotEquals(0, dc.decide(w).turnDegPerS());
        assertEquals(0, dc.decide(w).vx(), 1e-9);
    }
}

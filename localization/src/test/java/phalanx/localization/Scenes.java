package phalanx.localization;

import phalanx.comm.perception.FootForce;
import phalanx.comm.perception.GameState;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.SeenPlayer;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.comm.perception.Vision;
import phalanx.model.robot.NaoModel;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;

import java.util.ArrayList;
import java.util.List;

/** Builds exact synthetic perceptions of an upright type-0 robot, head straight, for tests. */
public final class Scenes {
    private Scenes() {}

    /** Camera height of an upright type-0 robot with straight legs: 0.385 + 0.155 m. */
    public static final double CAMERA_HEIGHT = NaoModel.ofType(0).standingTorsoHeight() + 0.155;

    /** What the camera of a robot at this pose (own frame) sees of a point (own frame, z up), head straight. */
    public static Polar polar(Pose2 pose, double x, double y, double z) {
        double dx = x - pose.x(), dy = y - pose.y(), dz = z - CAMERA_HEIGHT;
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double h = Math.toDegrees(Math.atan2(dy, dx)) - pose.thetaDeg();
        h = Math.IEEEremainder(h, 360);
        double v = Math.toDegrees(Math.asin(dz / d));
        return new Polar(d, h, v);
    }

    /** Polar sightings of the given landmarks (null for the rest), for a team on this side. */
    public static Polar[] landmarks(FieldSpec f, Side side, Pose2 pose, Landmark... seen) {
        Polar[] out = new Polar[Landmark.COUNT];
        for (Landmark l : seen) {
            Vector3 p = f.landmark(l, side);
            out[l.ordinal()] = polar(pose, p.x(), p.y(), p.z());
        }
        return out;
    }

    public static Vision vision(Polar[] landmarks, Polar ball, List<SeenPlayer> players) {
        return new Vision(landmarks, ball, players, List.of(), null, Double.NaN, null);
    }

    /** Joints all at 0 (standing straight, head straight). */
    public static JointAngles straight() {
        return new JointAngles(new double[phalanx.comm.perception.Joint.COUNT]);
    }

    /** Two feet carrying 45 N, as the recordings show for a standing robot. */
    public static List<FootForce> standingFeet() {
        List<FootForce> f = new ArrayList<>();
        f.add(new FootForce(FootForce.Foot.LEFT, new Vector3(0, 0, -0.01), new Vector3(0, 0, 22.6)));
        f.add(new FootForce(FootForce.Foot.RIGHT, new Vector3(0, 0, -0.01), new Vector3(0, 0, 22.6)));
        return f;
    }

    public static final Vector3 UPRIGHT = new Vector3(0, 0, 9.81);

    /** A standing robot's perception with this vision (null: no See this cycle). */
    public static Perception perception(double time, Vision v) {
        return new Perception(time, null, Vector3.ZERO, UPRIGHT, straight(), standingFeet(), v, List.of(), List.of());
    }

    /** The first message after init: GS with our number and side. */
    public static Perception gameState(double time, int unum, Side side) {
        GameState gs = new GameState(0, PlayMode.BEFORE_KICK_OFF, "BeforeKickOff", unum, side, 0, 0);
        return new Perception(time, gs, Vector3.ZERO, UPRIGHT, straight(), standingFeet(), null, List.of(), List.of());
    }
}

package phalanx.agent.mj;

import phalanx.comm.mj.MjPerception;
import phalanx.model.field.Angles;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.model.robot.T1Model;

/**
 * What a T1 player on rcssservermj knows, in its team's own frame (the world frame for the left team, turned by
 * 180° for the right): its pose from the server's ground-truth torso sensors, the ball from its own vision through
 * the camera chain ({@link T1Model#seenToWorld}), the play mode and our side. No filter: the server's pose and
 * noiseless vision need none (docs/rcssservermj.md); the thesis filter runs on SimSpark only, so far.
 */
public final class MjWorld {
    /** Below this z of the torso's up axis (about 60° of tilt) the robot counts as fallen. */
    static final double UPRIGHT_MIN = 0.5;

    private final String team;
    private int side;           // +1 left, -1 right, 0 unknown yet
    private double time = Double.NaN;
    private String playMode = "";
    private Pose2 self;
    private boolean upright = true;
    private Vector2 ball;
    private double ballSeenAt = Double.NEGATIVE_INFINITY;
    private long updates;

    public MjWorld(String team) { this.team = team; }

    public void update(MjPerception p) {
        updates++;
        if (Double.isFinite(p.time())) time = p.time();
        if (p.playMode() != null) playMode = p.playMode();
        if (side == 0) side = team.equals(p.teamLeft()) ? 1 : team.equals(p.teamRight()) ? -1 : 0;
        if (p.quat() != null && p.pos() != null) {
            double heading = T1Model.headingDeg(p.quat());
            self = own(new Pose2(p.pos()[0], p.pos()[1], heading));
            upright = T1Model.uprightness(p.quat()) >= UPRIGHT_MIN;
            double[] yaw = p.joints().get("q_hj1"), pitch = p.joints().get("q_hj2");
            for (MjPerception.Seen s : p.seen()) {
                if (!s.name().equals("B") || yaw == null || pitch == null) continue;
                double[] w = T1Model.seenToWorld(p.quat(), p.pos(), yaw[0], pitch[0], s.distance(), s.azimuth(), s.elevation());
                ball = own(new Vector2(w[0], w[1]));
                ballSeenAt = time;
            }
        }
    }

    private Pose2 own(Pose2 world) {
        return side >= 0 ? world : new Pose2(-world.x(), -world.y(), Angles.normalize(world.thetaDeg() + 180));
    }

    private Vector2 own(Vector2 world) {
        return side >= 0 ? world : new Vector2(-world.x(), -world.y());
    }

    /** +1 when we play on the left, -1 on the right, 0 before the server has named us. */
    public int side() { return side; }
    public double time() { return time; }
    public String playMode() { return playMode; }
    /** Our pose in our own frame, null before the first torso reading. */
    public Pose2 self() { return self; }
    public boolean upright() { return upright; }
    /** The ball in our own frame as last seen, null if never seen. */
    public Vector2 ball() { return ball; }
    /** Seconds since the ball was last seen (infinite if never). */
    public double ballAge() { return ball == null ? Double.POSITIVE_INFINITY : time - ballSeenAt; }
    public long updates() { return updates; }

    /** Whether the server lets robots beam now (games/soccer/sim/soccer_referee.py is_beaming_allowed). */
    public boolean beamAllowed() {
        return playMode.equals("BeforeKickOff") || playMode.startsWith("Goal_");
    }

    /** True for a play mode that is ours: "KickOff_Left" when we are left, and so on. */
    public boolean ours(String mode) {
        String m = mode.toLowerCase();
        return side > 0 ? m.endsWith("_left") : side < 0 && m.endsWith("_right");
    }
}

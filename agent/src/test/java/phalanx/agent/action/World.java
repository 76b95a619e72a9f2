package phalanx.agent.action;

import phalanx.agent.decide.Situation;
import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.PlayMode;
import phalanx.comm.perception.Side;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.localization.fall.FallState;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

import java.util.ArrayList;
import java.util.List;

/** Builds synthetic situations for action tests: WorldBelief records made by hand, own frame, left side. */
public final class World {
    public double now = 10;
    public Pose2 self = new Pose2(0, 0, 0);
    public double confidence = 0.9, selfAge = 0;
    public Vector2 ballRel, ballGlobal, ballVelocity;
    public double ballAge = Double.POSITIVE_INFINITY;
    /** The ball fields are the teammates' report, not own sight (WorldBelief.ballHeard). */
    public boolean ballHeard;
    public final List<PlayerBelief> mates = new ArrayList<>(), opponents = new ArrayList<>();
    public FallState fall = FallState.STANDING;
    public Situation.MotionStatus motion = Situation.MotionStatus.IDLE;
    public PlayMode mode = PlayMode.PLAY_ON;
    public FieldSpec field = FieldSpec.V066;

    public static World at(double x, double y, double theta) {
        World w = new World();
        w.self = new Pose2(x, y, theta);
        return w;
    }

    /** No self belief at all. */
    public static World lost() {
        World w = new World();
        w.self = null;
        w.confidence = 0;
        w.selfAge = Double.POSITIVE_INFINITY;
        return w;
    }

    /** The ball at a body-relative point, seen now; its global position follows from the self pose. */
    public World ballRel(double x, double y) {
        ballRel = new Vector2(x, y);
        ballGlobal = self == null ? null : self.toGlobal(ballRel);
        ballAge = 0;
        return this;
    }

    /** The ball at an own-frame point, seen now. */
    public World ballAt(double x, double y) {
        ballGlobal = new Vector2(x, y);
        ballRel = self.toRelative(ballGlobal);
        ballAge = 0;
        return this;
    }

    /** The ball as the teammates report it (said {@code age} s ago), not seen. */
    public World heard(double age) { ballHeard = true; ballAge = age; return this; }

    public World ballVelocity(double vx, double vy) { ballVelocity = new Vector2(vx, vy); return this; }

    public World teammateAt(int id, double x, double y) { mates.add(player("Phalanx", id, x, y)); return this; }

    public World opponentAt(int id, double x, double y) { opponents.add(player("Them", id, x, y)); return this; }

    private PlayerBelief player(String team, int id, double x, double y) {
        Vector2 g = new Vector2(x, y);
        Vector2 rel = self == null ? g : self.toRelative(g);
        return new PlayerBelief(team, id, now, rel, self == null ? null : g,
                new Vector2[BodyPart.COUNT], self);
    }

    public World fall(FallState f) { fall = f; return this; }

    public World motion(String playing, String last, long completions) {
        motion = new Situation.MotionStatus(playing, last, completions);
        return this;
    }

    public World time(double t) { now = t; return this; }

    public WorldBelief belief() {
        return new WorldBelief(now, Side.LEFT, 5, self, confidence, selfAge, ballRel, ballGlobal, ballAge, ballVelocity,
                List.copyOf(mates), List.copyOf(opponents), fall, ballHeard);
    }

    public Situation situation() {
        return new Situation(now, (long) (now / 0.02), mode, now, belief(), field, JointAngles.none(), motion);
    }
}

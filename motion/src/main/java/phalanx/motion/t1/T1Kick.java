package phalanx.motion.t1;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * A T1 kick for rcssservermj in the style of FC Portugal's Slot_Engine: a list of keyframes ({@link T1KickConfig})
 * reached one after the other by linear interpolation, each keyframe a torso sway over the support foot and the
 * feet's offsets from the gait's stand pose, turned into joint angles by {@link T1LegKinematics} (soles level) and
 * sent as the same PD {@link JointCommand}s as {@link T1Gait}. Written for the right foot, mirrored for the left.
 * It ends in the gait's stand pose, so {@link T1Gait#stand()} / {@code next} can take over.
 */
public final class T1Kick {
    private static final String[] LEFT = {"lle1", "lle2", "lle3", "lle4", "lle5", "lle6"};
    private static final String[] RIGHT = {"rle1", "rle2", "rle3", "rle4", "rle5", "rle6"};

    private final T1GaitConfig g;
    private final T1KickConfig c;
    private final T1LegKinematics leftLeg, rightLeg;
    private final List<JointCommand> upperBody;
    private final double[] qLeft = {-0.3, 0, 0, 0.6, -0.3, 0}, qRight = {-0.3, 0, 0, 0.6, -0.3, 0};
    private final double[] prevLeft = new double[6], prevRight = new double[6];
    private boolean leftFoot, active;
    private int phase;
    private double t;

    public T1Kick(T1GaitConfig gait, T1KickConfig kick) {
        this.g = gait;
        this.c = kick;
        this.leftLeg = new T1LegKinematics(gait, true);
        this.rightLeg = new T1LegKinematics(gait, false);
        // arms, head and waist as the gait holds them
        this.upperBody = new T1Gait(gait).stand().stream().filter(j -> !j.actuator().matches("[lr]le\\d")).toList();
    }

    public T1KickConfig config() { return c; }

    /** Starts a kick with the left or right foot; empty if started, else why not (the robot is unchanged then). */
    public Optional<String> start(boolean left, boolean upright) {
        if (!upright) return Optional.of("not upright: get up before kicking");
        if (active) return Optional.of("already kicking (phase " + phaseName() + ")");
        leftFoot = left;
        active = true;
        phase = 0;
        t = 0;
        pose(new double[7], qLeft, qRight);             // the stand pose as the start of the first phase
        System.arraycopy(qLeft, 0, prevLeft, 0, 6);
        System.arraycopy(qRight, 0, prevRight, 0, 6);
        return Optional.empty();
    }

    public boolean active() { return active; }

    /** Ends a running kick at once (a fall); the next {@link #next} gives the stand pose. */
    public void stop() { active = false; }
    public boolean leftFoot() { return leftFoot; }

    /** The phase being played, or "done". */
    public String phaseName() { return active ? c.phases().get(phase).name() : "done"; }

    /** One control cycle (the gait's dt); after the last phase the stand pose, and {@link #active()} is false. */
    public List<JointCommand> next() {
        double[] target = new double[7];
        if (active) {
            t += g.dt();
            while (active && t >= c.phases().get(phase).seconds() - 1e-9) {
                t -= c.phases().get(phase).seconds();
                if (++phase == c.phases().size()) active = false;
            }
            if (active) {
                double[] a = phase == 0 ? new double[7] : values(c.phases().get(phase - 1)), b = values(c.phases().get(phase));
                double s = t / c.phases().get(phase).seconds();
                for (int k = 0; k < 7; k++) target[k] = a[k] + (b[k] - a[k]) * s;
            }
        }
        pose(target, qLeft, qRight);
        List<JointCommand> out = new ArrayList<>(23);
        for (int k = 0; k < 6; k++) {
            boolean ankle = k >= 4;
            double kp = ankle ? c.ankleKp() : c.legKp(), kd = ankle ? c.ankleKd() : c.legKd();
            double dl = active ? (qLeft[k] - prevLeft[k]) / g.dt() : 0, dr = active ? (qRight[k] - prevRight[k]) / g.dt() : 0;
            out.add(new JointCommand(LEFT[k], Math.toDegrees(qLeft[k]), Math.toDegrees(dl), kp, kd, 0));
            out.add(new JointCommand(RIGHT[k], Math.toDegrees(qRight[k]), Math.toDegrees(dr), kp, kd, 0));
        }
        System.arraycopy(qLeft, 0, prevLeft, 0, 6);
        System.arraycopy(qRight, 0, prevRight, 0, 6);
        out.addAll(upperBody);
        return out;
    }

    private static double[] values(T1KickConfig.Phase p) {
        return new double[]{p.sway(), p.kickX(), p.kickY(), p.kickZ(), p.kickPitch(), p.supportX(), 0};
    }

    /** Joint angles for {sway, kickX, kickY, kickZ, kickPitch, supportX} (right-foot kick, mirrored if left). */
    private void pose(double[] v, double[] ql, double[] qr) {
        double s = leftFoot ? -1 : 1;                    // +1: the left foot supports
        double sway = s * v[0];
        double kx = g.footX() + v[1], ky = -s * g.footY() + s * v[2], kz = g.footZ() + v[3];
        double sx = g.footX() + v[5], sy = s * g.footY();
        double[] kick = leftFoot ? ql : qr, support = leftFoot ? qr : ql;
        (leftFoot ? leftLeg : rightLeg).inverse(kx, ky - sway, kz, 0, kick);
        (leftFoot ? rightLeg : leftLeg).inverse(sx, sy - sway, g.footZ(), 0, support);
        double[][] range = (leftFoot ? leftLeg : rightLeg).ranges();
        kick[4] = T1Gait.clamp(kick[4] + v[4], range[4][0], range[4][1]);
    }
}

package phalanx.motion.t1;

import phalanx.model.robot.T1Model;
import phalanx.motion.MotionFileException;

import java.nio.file.Path;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * Getting the T1 up after a fall on rcssservermj: once the torso is tilted past {@link Config#fallenTiltDeg()},
 * wait until it lies still (or {@link Config#maxWaitS()}), play get_up_front or get_up_back (motions/t1,
 * {@link T1MotionPlayer}) for the side it lies on, and if it is still down at the end, start again. The referee
 * takes a field player off after 15 s on the ground (docs/rcssservermj.md), so a get-up must not wait long.
 */
public final class T1GetUp {
    /**
     * @param fallenTiltDeg torso up axis this far from vertical = fallen (the agent's upright test: 60 deg)
     * @param stillDegS     lying still: gyro below this, deg/s, on both tilt axes
     * @param maxWaitS      longest wait for lying still before the get-up starts anyway, s
     */
    public record Config(double fallenTiltDeg, double stillDegS, double maxWaitS) {
        public static final Config DEFAULT = new Config(60, 30, 1.0);
    }

    public enum State { UP, LYING, GETTING_UP }

    private final T1Motion front, back;
    private final Config c;
    private final T1MotionPlayer player;
    private State state = State.UP;
    private double lyingSince;
    private long getUps, retries;
    private boolean failed;   // the last get-up ended with the robot still down

    public T1GetUp(T1Motion front, T1Motion back, Config config, double dt) {
        this.front = front;
        this.back = back;
        this.c = config;
        this.player = new T1MotionPlayer(dt, T1MotionPlayer.Gains.DEFAULT);
    }

    /** get_up_front.motion and get_up_back.motion from a folder (motions/t1). */
    public static T1GetUp load(Path dir, double dt) throws MotionFileException {
        return new T1GetUp(T1MotionLoader.load(dir.resolve("get_up_front.motion")), T1MotionLoader.load(dir.resolve("get_up_back.motion")),
                Config.DEFAULT, dt);
    }

    public State state() { return state; }

    /** Get-ups started so far. */
    public long getUps() { return getUps; }

    /** Of those, the ones started because the one before ended with the robot still down. */
    public long retries() { return retries; }

    /** The motion playing, or null. */
    public String playing() { return state == State.GETTING_UP ? player.motion().name() : null; }

    /**
     * One cycle: the torso quaternion (w, x, y, z), the gyro (deg/s), the measured joint angles (deg, by actuator)
     * and the time (s). Returns the get-up's joint commands while it is in control, or null when the robot is up
     * (then the caller's gait acts; while lying still before a get-up, too).
     */
    public List<JointCommand> update(double[] quat, double[] gyroDegS, ToDoubleFunction<String> measuredDeg, double time) {
        if (state == State.GETTING_UP) {
            List<JointCommand> out = player.next();
            if (!player.active()) state = fallen(quat) ? State.LYING : State.UP;
            if (state == State.LYING) {
                lyingSince = time;
                failed = true;
            }
            return out;
        }
        if (!fallen(quat)) {
            state = State.UP;
            failed = false;
            return null;
        }
        if (state == State.UP) {
            state = State.LYING;
            lyingSince = time;
        }
        boolean still = gyroDegS == null || (Math.abs(gyroDegS[0]) < c.stillDegS() && Math.abs(gyroDegS[1]) < c.stillDegS());
        if (!still && time - lyingSince < c.maxWaitS()) return null;
        state = State.GETTING_UP;
        getUps++;
        if (failed) retries++;
        failed = false;
        player.start(faceDown(quat) ? front : back, measuredDeg);
        return player.next();
    }

    boolean fallen(double[] q) {
        return T1Model.uprightness(q) < Math.cos(Math.toRadians(c.fallenTiltDeg()));
    }

    /** Whether the torso's forward (x) axis points down more than up: lying on the front. */
    static boolean faceDown(double[] q) {
        double w = q[0], x = q[1], y = q[2], z = q[3];
        return 2 * (x * z - w * y) < 0;
    }
}

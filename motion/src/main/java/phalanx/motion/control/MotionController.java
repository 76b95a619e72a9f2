package phalanx.motion.control;

import phalanx.comm.perception.Joint;
import phalanx.comm.perception.JointAngles;
import phalanx.comm.perception.Vector3;
import phalanx.motion.Motion;
import phalanx.motion.MotionConfig;
import phalanx.motion.MotionLibrary;
import phalanx.model.robot.JointLimits;
import phalanx.motion.phase.Check;
import phalanx.motion.phase.Phase;
import phalanx.motion.phase.PhaseMotion;
import phalanx.motion.webots.TextMotion;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import java.util.logging.Logger;

/**
 * The motion controller (4.5.2, 4.5.4): reads the requested-motion variable every cycle and
 * continues the playing motion, finalizes it toward its final phase, or starts the requested one.
 *
 * <p>Phase motions: a phase of duration D lasts n = round(D / cycle) cycles (at least one); in its
 * k-th cycle each listed joint gets (target - current) / ((n - k) cycles), every other joint 0.
 * When the joint follows, that is the thesis's constant (target - start) / D; when it lags, the
 * remaining cycles catch up. Text motions: each pose lasts Duration cycles, poses advance by
 * PoseStep, and v = gain * (target - current) / (Duration * cycle) (4.5.4).
 *
 * <p>"current" is the reading plus the command already on its way: the server applies a command
 * one cycle after the reading it answers (recordings README), so the reading lags by one command
 * ({@link MotionConfig#latencyCycles()}; 0 gives the thesis's formula unchanged).
 *
 * <p>A phase with a {@link Check} tests the torso's orientation (the accelerometer) when it ends and,
 * when the torso is not where the motion expects it, goes to the check's else phase (once per
 * play) or switches to another motion, which then plays as the continuation of the same request.
 *
 * <p>Values in, values out: time is the caller's (server time in seconds), no clock, no socket.
 * One instance per player; not thread-safe.
 */
public final class MotionController {
    private static final Joint[] JOINTS = Joint.values();
    private static final Logger LOG = Logger.getLogger(MotionController.class.getName());

    private final MotionLibrary library;
    private final MotionConfig config;
    private final double dt;
    private final double[] lastCommand = new double[Joint.COUNT]; // rad/s, 0 when none was sent
    private final double[] targets = new double[Joint.COUNT];     // this phase's targets, deg, NaN = unlisted
    private final Set<String> warnedUnknown = new HashSet<>();

    private Motion playing;          // null when idle
    private String requestedAs;      // the request that started this play (differs from playing after a check's switch)
    private boolean[] elseTaken = new boolean[0]; // per phase: its check's else already taken in this play
    private Vector3 acc;             // this cycle's accelerometer reading, null when none
    private int index;               // phase or pose index
    private double segmentStart;     // server time the phase/pose started
    private int segmentCycles;       // its length in cycles
    private boolean finalizing;      // on the way to the end (entered a finalize link, or a text motion's last pass)
    private long completions;
    private String lastCompleted;
    private double lastNow = Double.NaN;

    public MotionController(MotionLibrary library, MotionConfig config) {
        this.library = library;
        this.config = config;
        this.dt = config.cycleSeconds();
    }

    /**
     * One cycle: the joint readings (degrees) of the message with time {@code now} (seconds) and the
     * request. Returns the hinge velocities to send in reply (rad/s, within the speed cap).
     */
    public JointVelocities step(double now, JointAngles current, MotionRequest request) {
        return step(now, current, null, request);
    }

    /**
     * One cycle with the accelerometer reading ({@code acc}, m/s², server torso frame; null when
     * none), which the phases' torso checks test. Without a reading every check passes.
     */
    public JointVelocities step(double now, JointAngles current, Vector3 acc, MotionRequest request) {
        this.acc = acc;
        // A message without a time, or one that does not come after the last: count it as the next
        // cycle. (The server's clock is a float: after 2^18 s of a free-running server it no longer
        // moves by 0.02 s, seen on rcssserver3d 0.7.3 left running without agents.)
        if (!Double.isFinite(now) || (!Double.isNaN(lastNow) && now <= lastNow)) now = Double.isNaN(lastNow) ? 0 : lastNow + dt;
        lastNow = now;
        String wanted = request.motion();
        if (wanted != null && library.get(wanted) == null) {
            if (warnedUnknown.add(wanted)) LOG.warning("no motion named '" + wanted + "' (have " + library.names() + "); standing still");
            wanted = null;
        }
        if (playing != null && request.interrupt() && !requestedAs.equals(wanted)) {
            playing = null; // aborted, not completed
        }
        if (playing != null) advance(now, wanted, request);
        if (playing == null && wanted != null) start(library.get(wanted), now, request);

        double[] out = new double[Joint.COUNT];
        if (playing instanceof PhaseMotion) {
            int remaining = Math.max(1, segmentCycles - elapsedCycles(now));
            for (Joint j : JOINTS) out[j.ordinal()] = phaseVelocity(j, current, remaining);
        } else if (playing instanceof TextMotion tm) {
            double gain = Math.max(config.turnGainMin(), Math.min(config.turnGainMax(), request.gain()));
            Arrays.fill(targets, Double.NaN);
            for (int k = 0; k < tm.joints().size(); k++) targets[tm.joints().get(k).ordinal()] = tm.targetDeg(index, k);
            for (Joint j : JOINTS) {
                double v = phaseVelocity(j, current, config.textPoseCycles());
                out[j.ordinal()] = Double.isNaN(v) ? v : clamp(gain * v);
            }
        } else {
            for (Joint j : JOINTS) out[j.ordinal()] = current.has(j) ? 0.0 : Double.NaN;
        }
        for (int i = 0; i < out.length; i++) lastCommand[i] = Double.isNaN(out[i]) ? 0 : out[i];
        return new JointVelocities(out);
    }

    /**
     * The name of the request being played, or null when idle. After a check's switch this is still
     * the motion that was requested (the switched one plays as its continuation; the agent's one-shot
     * tracking sees one play); {@link #playingMotion()} names the one whose phases play.
     */
    public String playing() { return playing == null ? null : requestedAs; }

    /** The motion whose phases are playing (differs from {@link #playing()} after a switch), or null. */
    public String playingMotion() { return playing == null ? null : playing.name(); }

    /** The playing phase's (or pose's) name, or null when idle. */
    public String segment() {
        if (playing instanceof PhaseMotion pm) return pm.phase(index).name();
        if (playing instanceof TextMotion tm) return tm.poseNames().get(index);
        return null;
    }

    /** True once the playing motion has taken a finalize link (4.5.2) and is on its way to the end. */
    public boolean finalizing() { return finalizing; }

    /** How many motions have played to their end (aborted ones do not count). */
    public long completions() { return completions; }

    /** The request that ended last (its name as requested, also after a switch), or null. */
    public String lastCompleted() { return lastCompleted; }

    private double phaseVelocity(Joint j, JointAngles current, int remainingCycles) {
        if (!current.has(j)) return Double.NaN;
        double target = targets[j.ordinal()];
        if (Double.isNaN(target)) return 0.0;
        double predicted = current.degrees(j) + config.latencyCycles() * Math.toDegrees(lastCommand[j.ordinal()]) * dt;
        return clamp(Math.toRadians(target - predicted) / (remainingCycles * dt));
    }

    private double clamp(double v) { return Math.max(-config.maxJointSpeed(), Math.min(config.maxJointSpeed(), v)); }

    private int elapsedCycles(double now) { return (int) Math.round((now - segmentStart) / dt); }

    private void start(Motion m, double now, MotionRequest request) {
        requestedAs = m.name();
        play(m, now, request);
    }

    private void play(Motion m, double now, MotionRequest request) {
        playing = m;
        elseTaken = m instanceof PhaseMotion pm ? new boolean[pm.phases().size()] : new boolean[0];
        finalizing = false;
        index = m instanceof PhaseMotion pm ? pm.first() : 0;
        enter(now, request);
    }

    /** Ends the phase or pose whose time is up, moving on as 4.5.2 / 4.5.4 say. */
    private void advance(double now, String wanted, MotionRequest request) {
        if (elapsedCycles(now) < segmentCycles) return;
        boolean same = requestedAs.equals(wanted);
        int nextIndex;
        if (playing instanceof PhaseMotion pm) {
            Phase p = pm.phase(index);
            if (finalizing || !same) {
                if (p.finalizeTo() >= 0) {
                    nextIndex = p.finalizeTo();
                    finalizing = true;
                } else {
                    nextIndex = p.next();
                }
            } else {
                nextIndex = p.next();
                Check c = p.check();
                if (c != null && !c.passes(acc)) {
                    if (c.elsePhase() >= 0 && !elseTaken[index]) {
                        elseTaken[index] = true;
                        nextIndex = c.elsePhase();
                        LOG.info(pm.name() + ": phase " + p.name() + " found the torso's " + c.axis() + " share at "
                                + String.format(java.util.Locale.ROOT, "%.2f", c.axis().share(acc)) + ", going to " + pm.phase(nextIndex).name());
                    } else if (c.switchTo() != null && library.get(c.switchTo()) != null) {
                        LOG.info(pm.name() + ": phase " + p.name() + " found the torso's " + c.axis() + " share at "
                                + String.format(java.util.Locale.ROOT, "%.2f", c.axis().share(acc)) + ", switching to " + c.switchTo());
                        play(library.get(c.switchTo()), now, request);
                        return;
                    }
                }
            }
        } else {
            TextMotion tm = (TextMotion) playing;
            int last = tm.poseCount() - 1;
            nextIndex = index == last ? -1 : Math.min(index + config.textPoseStep(), last);
            if (nextIndex < 0 && same) nextIndex = 0; // turns repeat while requested
        }
        if (nextIndex < 0) {
            completions++;
            lastCompleted = requestedAs;
            playing = null;
            return;
        }
        index = nextIndex;
        enter(now, request);
    }

    private void enter(double now, MotionRequest request) {
        segmentStart = now;
        if (playing instanceof PhaseMotion pm) {
            Phase p = pm.phase(index);
            double scale = request.slowdown() ? config.walkSlowdownFactor() : 1.0;
            segmentCycles = Math.max(1, (int) Math.round(p.durationMs() * scale / 1000.0 / dt));
            for (Joint j : JOINTS) targets[j.ordinal()] = p.targetDeg(j);
            lean(p, request.lean());
        } else {
            segmentCycles = config.textPoseCycles();
        }
    }

    /**
     * Walk Leaning (4.5.5): in the phases where the leaning side's leg swings forward, that leg's
     * hip pitch is reduced and its ankle pitch raised by the same amount (the foot stays parallel to
     * the torso), so it takes a shorter step and the walk curves toward it.
     */
    private void lean(Phase p, double lean) {
        Joint hip, ankle;
        if (lean > 0 && p.swing() == Phase.Swing.LEFT) { hip = Joint.LLJ3; ankle = Joint.LLJ5; }
        else if (lean < 0 && p.swing() == Phase.Swing.RIGHT) { hip = Joint.RLJ3; ankle = Joint.RLJ5; }
        else return;
        double delta = Math.abs(lean) * config.walkLeanDeg();
        if (!Double.isNaN(targets[hip.ordinal()])) targets[hip.ordinal()] = JointLimits.clamp(hip, targets[hip.ordinal()] - delta);
        if (!Double.isNaN(targets[ankle.ordinal()])) targets[ankle.ordinal()] = JointLimits.clamp(ankle, targets[ankle.ordinal()] + delta);
    }
}

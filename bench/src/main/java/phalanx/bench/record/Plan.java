package phalanx.bench.record;

import phalanx.motion.walk.WalkVelocity;

import java.util.ArrayList;
import java.util.List;

/**
 * What one scripted robot does, step after step (measuring code, not a behaviour that plays): stand, walk with a
 * velocity, tip over by driving both ankle pitches (recording S3's way to fall), or get up (the get-up the
 * agent would choose). The head follows its own law all the time: yaw {@code panDeg}·sin(2πt/panS), pitch
 * {@code tiltMidDeg} + {@code tiltDeg}·sin(2πt/tiltS), t from the first cycle after the beam. The beam is in the
 * robot's own frame (a right player's is turned by 180°, as the server takes it).
 */
record Plan(double beamX, double beamY, double beamDeg, List<Step> steps,
            double panDeg, double panS, double tiltMidDeg, double tiltDeg, double tiltS) {

    enum Kind { STAND, WALK, TIP, GETUP }

    /**
     * One step: {@code cycles} long (a GETUP lasts until its motion completes, at most {@code cycles}); {@code walk}
     * for WALK; {@code ankle} (rad/s, both ankle pitches, negative tips it backwards) for TIP.
     */
    record Step(Kind kind, int cycles, WalkVelocity walk, double ankle) {}

    static Builder at(double x, double y, double deg) { return new Builder(x, y, deg); }

    /** Head yaw target at {@code t} s, degrees. */
    double headYawDeg(double t) { return panDeg == 0 ? 0 : panDeg * Math.sin(2 * Math.PI * t / panS); }

    /** Head pitch target at {@code t} s, degrees (positive looks up). */
    double headPitchDeg(double t) { return tiltMidDeg + (tiltDeg == 0 ? 0 : tiltDeg * Math.sin(2 * Math.PI * t / tiltS)); }

    /** Cycles from the first step to the end of the last (GETUP counted at its maximum). */
    int cycles() { return steps.stream().mapToInt(Step::cycles).sum(); }

    static final class Builder {
        private final double x, y, deg;
        private final List<Step> steps = new ArrayList<>();
        private double pan, panS = 1, tiltMid, tilt, tiltS = 1;

        private Builder(double x, double y, double deg) {
            this.x = x;
            this.y = y;
            this.deg = deg;
        }

        Builder stand(double s) { return add(new Step(Kind.STAND, cycles(s), null, 0)); }
        Builder walk(double s, double forward, double left, double turnDeg) {
            return add(new Step(Kind.WALK, cycles(s), new WalkVelocity(forward, left, turnDeg), 0));
        }
        /** Both ankle pitches at {@code radPerS} for 0.5 s (S3: -2 rad/s for 25 cycles falls on the back). */
        Builder tip(double radPerS) { return add(new Step(Kind.TIP, 25, null, radPerS)); }
        Builder getUp() { return add(new Step(Kind.GETUP, 400, null, 0)); }
        Builder pan(double deg, double periodS) { pan = deg; panS = periodS; return this; }
        Builder tilt(double midDeg, double deg, double periodS) { tiltMid = midDeg; tilt = deg; tiltS = periodS; return this; }

        private Builder add(Step s) { steps.add(s); return this; }
        private static int cycles(double s) { return (int) Math.round(s / 0.02); }

        Plan build() { return new Plan(x, y, deg, List.copyOf(steps), pan, panS, tiltMid, tilt, tiltS); }
    }
}

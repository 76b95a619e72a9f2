package phalanx.localization;

/**
 * Every constant of the localization module, in one place. Thesis values are the defaults and say
 * where they come from; constants the thesis does not give were chosen here and measured with
 * {@code scripts/phalanx bench localize} (localization/README.md).
 *
 * @param filter               which self-localization filter the belief store runs
 * @param fifoMaxSize          Algorithm 1's MaxSize (thesis 4.4.3: default 10)
 * @param selfAgreementMetres  Algorithm 1's "agrees" for self positions; not in the thesis (DESIGN.md, gaps)
 * @param selfAgreementDeg     the same for the body orientation; not in the thesis
 * @param ballAgreementMetres  Algorithm 1's "agrees" for the ball (4.4.3 filters the ball too); not in the thesis
 * @param pairWeighting        how pair fixes are averaged: EQUAL is the thesis's plain mean (4.4.1)
 * @param fieldMarginMetres    a candidate further outside the lines than this is "way outside" (4.4.1)
 * @param ekfPositionNoise     EKF process noise per cycle, metres (beyond the thesis, its 7.x future work)
 * @param ekfAngleNoiseDeg     EKF process noise per cycle, degrees
 * @param relocateFrames       k: vision frames in a row that disagree with the self belief (their pair fix
 *                             farther than relocateMetres or relocateDeg from it; for the EKF also every landmark
 *                             outside its gate) and agree with each other (relocateSpread*) after which the filter
 *                             is re-initialised at the new pose instead of refusing them (beam after a goal,
 *                             trainer or referee move). Not in the thesis: Algorithm 1 alone needs MaxSize
 *                             refusals to empty its queue (19-34 cycles over 1 m in the recordings, issue 19).
 *                             2 is the least that still ignores a single outlier frame; with a See every third
 *                             cycle the belief is back at most 2 steady vision frames after the move
 *                             (localization/README.md, "Per recording (issue 19)"). Replaces the EKF's earlier
 *                             ekfResetFrames (3 frames, position only, no agreement between the frames). Since the
 *                             single-frame rule (relocateResidual*) this is the fallback for far frames whose
 *                             landmarks do not agree with each other
 * @param relocateMetres       "far from the belief" for relocateFrames: Algorithm 1's self agreement (0.5 m);
 *                             the pair fixes of upright frames in the eight recordings are at most 0.30 m off
 *                             the true torso (S3 leaning before its fall), 0.23 m otherwise; not in the thesis
 * @param relocateDeg          the same for the heading (15°, Algorithm 1's; the fixes' heading errors stay
 *                             under 0.6°); a heading-only move counts too; not in the thesis
 * @param relocateSpreadMetres "close to each other" for relocateFrames: each disagreeing fix within this of the
 *                             previous one, else the count starts again from it (0.5 m); not in the thesis
 * @param relocateSpreadDeg    the same for the heading (15°); not in the thesis
 * @param relocateResidualMetres a single vision frame re-initialises the self belief at once (issue 19, not in the
 *                             thesis) when its pair fix is far from the belief (relocateMetres/relocateDeg; EKF:
 *                             every landmark outside the gate) and every landmark seen agrees with that fix: the
 *                             landmark's ground vector is within relocateResidualMetres + relocateResidualShare x
 *                             its distance of where the fix puts it. 0.1 m; upright frames of the eight recordings
 *                             are within 0.27 m at up to 30 m (at most 1.0 % of the distance; the first frames after
 *                             the three moves 0.04-0.08 m). NaN: off (then relocateFrames frames as before)
 * @param relocateResidualShare the share of the landmark's distance in that tolerance (0.02); not in the thesis
 * @param trackSetSize         Track Moving Object: observations per set (thesis 4.6: five)
 * @param trackDelay           Track Moving Object: delay between the two sets, observations (thesis 4.6: five)
 * @param fusionClusterMetres  team ball fusion cluster threshold (thesis 5.4: 1 m)
 * @param fusionWeightExponent team ball fusion cluster weight |s|^k (thesis 5.4: k = 3)
 * @param fallTiltDeg          torso tilt from vertical (accelerometer) that signals a possible fall; not in the thesis
 * @param fallGyroDegPerSec    gyro rate that signals a possible fall; not in the thesis
 * @param fallSupportNewtons   total sole-normal foot force under which the feet "do not carry" the robot
 *                             (thesis 4.6 Stand Up confirms with the foot sensors); standing gives about 45 N
 * @param fallConfirmCycles    cycles the tilt and the missing support must last before a fall is confirmed
 * @param fallBackMinDeg       a confirmed fall is FALLEN_BACK only when the torso's forward axis points this far above
 *                             the horizontal; lying on a side (or nearly) counts as FALLEN_FRONT. With the chest
 *                             near horizontal the sign of the forward axis is noise and would flip the choice
 *                             between retries; both get-ups stood about 2 in 3 side-lying trials
 *                             (motion/README.md, scripts/phalanx bench motion); not in the thesis
 * @param accSmoothing         share of the accelerometer mixed into the gyro-integrated tilt per cycle; not in the thesis
 * @param fallTiltCycles       cycles in a row the accelerometer must show the tilt before it says "falling": in the
 *                             real server the omni walk's foot impacts tilt single readings past 90° (81 of 500
 *                             walking cycles over 50°, never two in a row; localization/README.md); not in the thesis
 * @param fallStuckCycles      cycles of uninterrupted tilt after which the fall counts as confirmed even with the feet
 *                             carrying weight (kneeling, sitting, tangled with another robot): otherwise a robot stuck
 *                             half down stayed FALLING, which only stands and waits; not in the thesis (ours: 1 s)
 * @param ballMissFrames       steady vision frames in a row in which the believed ball lay inside the camera's view
 *                             (ballMissViewDeg) and no ball was seen, after which the ball belief is dropped: the
 *                             server's restricted vision has no occlusion, so a ball in the view cone is always
 *                             reported. In session 21's g1 a player kept a kicked ball "at its feet" for 6 s while it
 *                             lay 5 m ahead of it, 3 m from the opponents' goal (docs/matches.md). 0: off; not in the thesis
 * @param ballMissViewDeg      half-angle of the view cone (horizontal and vertical, from the camera's axis) inside which
 *                             a ball must be seen: the server's is 60° (120° x 120°, docs/protocol.md), less a margin
 *                             for the head's motion within a cycle and the torso tilt's error; not in the thesis
 * @param fifoFixSigmaMetres   the FIFO filter's motion weighting (issue 19, not in the thesis; NaN odometryErrorShare: off,
 *                             Algorithm 1's plain mean): the position noise of one pair fix, rms 0.04-0.05 m standing
 *                             (S1, turn-head, crowd, ball-roll; 0.10 m walking in walk-head) against the true torso
 * @param fifoFixSigmaDeg      the same for the heading: rms 0.14-0.22° over those recordings
 * @param odometryErrorShare   how far the walk's odometry is off, as a share of the motion it reports: turn-head commands
 *                             1.20°/cycle where the robot turns 1.10 (960° commanded, 855° turned), walk-head 6.85 m
 *                             commanded for 6.45 m walked. The FIFO weighs each queued fix by 1 / (sigma² + (share x
 *                             motion it was moved by)²), so fixes moved far by odometry count less: before, every queued
 *                             fix counted the same and the belief ran 2° ahead of the turn (turn-head, FIFO heading
 *                             median)
 * @param gyroTurn             the self belief turns between fixes by the gyro's rate about the vertical (GYR along the
 *                             tilt estimate's up, x the cycle), not by the odometry's turn; the odometry still gives the
 *                             forward and sideways steps. Not in the thesis (issue 19). Upright, the gyro's turn matches
 *                             the true yaw change of the same cycle to 0.008°/cycle rms (turn-head, walk-head, crowd;
 *                             211.2° summed for 212.3° turned over turn-head), the walk's odometry is 9 % off. Without
 *                             odometry the EKF's heading had stood still while the robot turned (turn-head: 61° behind
 *                             after 20 frames of one landmark or none): its heading sigma grows by ekfAngleNoiseDeg per
 *                             cycle only (1-3.8° there), so the chi² gate refused every single landmark. Measured in
 *                             recordings/README.md: heading p95 under 1° on every recording, both filters, with and
 *                             without odometry. false: the odometry's turn (as before)
 * @param ballRollMinSpeed     the ball's queued sightings move on between sightings with Track Moving Object's velocity
 *                             when it is at least this, m/s (issue 19, not in the thesis; +Infinity: off). A still ball's
 *                             tracked speed stays under 0.5 on walk-head(-right) and turn-head (at most 0.44-0.50), up to
 *                             0.75 after fall-right's get-up (FIFO); the trainer's rolls start at 6-7 m/s. Before, the belief (the queue's mean) trailed a rolling
 *                             ball by 0.2-0.4 m while every sighting was within 3 cm of it (ball-roll lines 140-160)
 * @param ballDecayPerSecond   the server's ball drag k, 1/s: v(t) = v0 e^(-kt), 1.062 measured for every start speed
 *                             (agent/README.md, bench ball-decay; keeper.ballDecay). The tracked velocity (the mean over
 *                             its window) is brought forward to now with it, and the prediction slows with it
 * @param ballRollAgreeShare   the prediction runs only while the last two sightings' displacement over their time agrees
 *                             with the tracked velocity within this share of the speed plus ballRollAgreeMps: a ball the
 *                             trainer placed elsewhere makes a jump in the tracker's window (crowd line 34: 2.99 m/s
 *                             for a ball lying still, carried 1.7 m off) and then shows no motion
 * @param ballRollAgreeMps     the fixed part of that tolerance, m/s (0.5: ball sightings 3 vision frames apart are
 *                             within 2-3 cm, about 0.4 m/s)
 * @param teamBallAfterSeconds  the ball belief falls back on the ball the teammates report (thesis 5.4's fusion of
 *                             their "C" reports, heard on the team channel) once the own ball was last seen longer
 *                             ago than this (1.0 s: the age under which a player reports its ball as seen,
 *                             agent's Reports.BALL_FRESH_S); not in the thesis, which fuses the reports on the
 *                             coordinator only (issue 19)
 * @param teamBallMemorySeconds a teammate's report counts for this long after it was said (1.5 s: one round of reports
 *                             is about 1 s with the default channel); not in the thesis
 */
public record LocalizationConfig(Filter filter, int fifoMaxSize, double selfAgreementMetres, double selfAgreementDeg,
                                 double ballAgreementMetres, PairWeighting pairWeighting, double fieldMarginMetres,
                                 double ekfPositionNoise, double ekfAngleNoiseDeg,
                                 int relocateFrames, double relocateMetres, double relocateDeg,
                                 double relocateSpreadMetres, double relocateSpreadDeg,
                                 double relocateResidualMetres, double relocateResidualShare,
                                 int trackSetSize, int trackDelay,
                                 double fusionClusterMetres, double fusionWeightExponent,
                                 double fallTiltDeg, double fallGyroDegPerSec, double fallSupportNewtons,
                                 int fallConfirmCycles, double fallBackMinDeg, double accSmoothing, int fallTiltCycles,
                                 int fallStuckCycles, int ballMissFrames, double ballMissViewDeg,
                                 double fifoFixSigmaMetres, double fifoFixSigmaDeg, double odometryErrorShare,
                                 boolean gyroTurn, double ballRollMinSpeed, double ballDecayPerSecond,
                                 double ballRollAgreeShare, double ballRollAgreeMps,
                                 double teamBallAfterSeconds, double teamBallMemorySeconds) {

    /** The self-localization filters the belief store can run. */
    public enum Filter { FIFO, EKF }

    /** How the fixes of landmark pairs are averaged. */
    public enum PairWeighting {
        /** The thesis's plain mean over the pairs (4.4.1). */
        EQUAL,
        /** Each pair weighted by sin² of the angle between its two sight lines: near-parallel pairs count little. */
        GEOMETRY
    }

    public static final LocalizationConfig DEFAULT = new LocalizationConfig(
            Filter.EKF, 10, 0.5, 15, 0.5, PairWeighting.GEOMETRY, 1.0,
            0.01, 0.5,
            2, 0.5, 15, 0.5, 15,
            0.1, 0.02,
            5, 5,
            1.0, 3,
            50, 150, 20, 5, 30, 0.05, 3, 50,
            3, 50,
            0.05, 0.2, 0.1,
            true, 0.5, 1.06, 0.5, 0.5,
            1.0, 1.5);

    public LocalizationConfig {
        if (filter == null || pairWeighting == null) throw new IllegalArgumentException("filter and pairWeighting are required");
        if (fifoMaxSize < 1) throw new IllegalArgumentException("fifoMaxSize must be at least 1, got " + fifoMaxSize);
        if (!(selfAgreementMetres > 0) || !(selfAgreementDeg > 0) || !(ballAgreementMetres > 0))
            throw new IllegalArgumentException("agreement thresholds must be positive");
        if (trackSetSize < 1 || trackDelay < 1) throw new IllegalArgumentException("track set size and delay must be at least 1");
        if (!(fusionClusterMetres > 0)) throw new IllegalArgumentException("fusionClusterMetres must be positive");
        if (!(accSmoothing > 0 && accSmoothing <= 1)) throw new IllegalArgumentException("accSmoothing must be in (0, 1]");
        if (!(fallBackMinDeg >= 0 && fallBackMinDeg < 90)) throw new IllegalArgumentException("fallBackMinDeg must be in [0, 90), got " + fallBackMinDeg);
        if (ballMissFrames < 0 || !(ballMissViewDeg > 0 && ballMissViewDeg < 90)) throw new IllegalArgumentException("ballMissFrames must be >= 0 and ballMissViewDeg in (0, 90)");
        if (!(teamBallAfterSeconds >= 0) || !(teamBallMemorySeconds >= 0))
            throw new IllegalArgumentException("teamBallAfterSeconds and teamBallMemorySeconds must be >= 0");
        if (relocateFrames < 1 || fallConfirmCycles < 1 || fallTiltCycles < 1 || fallStuckCycles < 1) throw new IllegalArgumentException("frame and cycle counts must be at least 1");
    }

    public LocalizationConfig withFilter(Filter f) {
        return new LocalizationConfig(f, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /** The same with other relocation constants (k frames, far metres and degrees, spread metres and degrees). */
    public LocalizationConfig withRelocation(int frames, double metres, double deg, double spreadMetres, double spreadDeg) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, frames, metres,
                deg, spreadMetres, spreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /**
     * The same with another single-frame relocation tolerance (metres plus share of the distance); NaN turns
     * the single-frame relocation off, leaving the relocateFrames rule.
     */
    public LocalizationConfig withRelocateResidual(double metres, double share) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, metres, share, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /** The same with another ball-miss rule (frames in a row, 0 = off; view half-angle in degrees). */
    public LocalizationConfig withBallMiss(int frames, double viewDeg) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                frames, viewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /** The same with another FIFO motion weighting (fix sigmas, odometry share; NaN share: Algorithm 1's plain mean). */
    public LocalizationConfig withOdometryWeighting(double sigmaMetres, double sigmaDeg, double share) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, sigmaMetres, sigmaDeg, share, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /** The same with the gyro's turn (true) or the odometry's (false) moving the self belief between fixes. */
    public LocalizationConfig withGyroTurn(boolean gyro) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyro, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    /** The same with another fall-back on the teammates' ball (own ball older than afterSeconds; reports kept memorySeconds). */
    public LocalizationConfig withTeamBall(double afterSeconds, double memorySeconds) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn,
                ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, afterSeconds, memorySeconds);
    }

    /** The same with another ball prediction (minimum speed, +Infinity: off; drag per second; agreement share and m/s). */
    public LocalizationConfig withBallPrediction(double minSpeed, double decayPerSecond, double agreeShare, double agreeMps) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                pairWeighting, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn,
                minSpeed, decayPerSecond, agreeShare, agreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }

    public LocalizationConfig withPairWeighting(PairWeighting w) {
        return new LocalizationConfig(filter, fifoMaxSize, selfAgreementMetres, selfAgreementDeg, ballAgreementMetres,
                w, fieldMarginMetres, ekfPositionNoise, ekfAngleNoiseDeg, relocateFrames, relocateMetres,
                relocateDeg, relocateSpreadMetres, relocateSpreadDeg, relocateResidualMetres, relocateResidualShare, trackSetSize,
                trackDelay, fusionClusterMetres, fusionWeightExponent, fallTiltDeg, fallGyroDegPerSec,
                fallSupportNewtons, fallConfirmCycles, fallBackMinDeg, accSmoothing, fallTiltCycles, fallStuckCycles,
                ballMissFrames, ballMissViewDeg, fifoFixSigmaMetres, fifoFixSigmaDeg, odometryErrorShare, gyroTurn, ballRollMinSpeed, ballDecayPerSecond, ballRollAgreeShare, ballRollAgreeMps, teamBallAfterSeconds, teamBallMemorySeconds);
    }
}

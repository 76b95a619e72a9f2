package phalanx.localization.belief;

import phalanx.comm.perception.BodyPart;
import phalanx.comm.perception.GameState;
import phalanx.comm.perception.Landmark;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.Polar;
import phalanx.comm.perception.SeenPlayer;
import phalanx.comm.perception.Side;
import phalanx.comm.perception.Vector3;
import phalanx.comm.perception.Vision;
import phalanx.localization.LocalizationConfig;
import phalanx.localization.body.CameraPose;
import phalanx.model.robot.NaoModel;
import phalanx.localization.body.TiltEstimator;
import phalanx.localization.fall.FallDetector;
import phalanx.localization.fall.FallState;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;
import phalanx.localization.filter.EkfPoseFilter;
import phalanx.localization.filter.FifoPoseFilter;
import phalanx.localization.filter.LocalizationFilter;
import phalanx.localization.filter.PoseFilter;
import phalanx.localization.team.BallFusion;
import phalanx.localization.tracking.MovingObjectTracker;
import phalanx.localization.vision.LandmarkSighting;
import phalanx.localization.vision.SelfLocalizer;

import java.util.ArrayList;
import java.util.List;

/**
 * The agent's beliefs (thesis 4.4 and 4.6), updated once per cycle with {@link #update(Perception)}:
 * the self pose from landmark pairs through the configured filter, the ball and the players seen
 * (thesis 4.4.2), the ball's motion (Track Moving Object), and the fall state (Stand Up).
 * The agent may feed its own walk's odometry with {@link #odometry}. Side and uniform number come
 * from the first GS message unless given. Not thread-safe: one per player, called from its loop.
 */
public final class BeliefStore {
    /** Highest uniform number kept; larger ids are ignored. */
    private static final int MAX_ID = 22;
    /** m/s² around 1 g within which the accelerometer's tilt is trusted. */
    private static final double STEADY_TOLERANCE = 3.0;
    /** Seconds per server cycle, for the first gyro step. */
    private static final double CYCLE = 0.02;
    /** The ball's centre above the ground, m (its radius). */
    private static final double BALL_CENTRE_HEIGHT = 0.042;

    private final FieldSpec field;
    private final LocalizationConfig config;
    private final NaoModel body;
    private final String teamName;
    private final SelfLocalizer localizer;
    private final PoseFilter selfFilter;
    private final LocalizationFilter ballFilter;
    private final MovingObjectTracker ballTracker;
    private final FallDetector fallDetector;
    private boolean bodyBusy;
    private final BeliefStats stats = new BeliefStats();
    private final List<LandmarkSighting> sightings = new ArrayList<>(Landmark.COUNT);
    private final PlayerBelief[] mates = new PlayerBelief[MAX_ID + 1], others = new PlayerBelief[MAX_ID + 1];

    private Side side;
    private int unum;
    private double time = Double.NaN, selfTime = Double.NEGATIVE_INFINITY, ballTime = Double.NEGATIVE_INFINITY;
    private final TiltEstimator tilt;
    private double lastTime = Double.NaN;
    private double odoForward, odoLeft, odoTurn;
    /** The rolling ball's velocity the ball queue is moved by each cycle (own frame, m/s); 0 while none is tracked. */
    private double ballVx, ballVy;
    /** The last ball sighting placed on the field (own frame) and its time, for {@link #rolling}. */
    private double lastSeenX, lastSeenY, lastSeenTime = Double.NaN;
    /** The self filter has had a belief since this store was made: a further start is a re-initialisation. */
    private boolean selfStarted;
    /** Steady vision frames in a row with the believed ball in view and no ball seen. */
    private int ballMisses;
    private Vector2 ballRelative;
    /** Each teammate's last reported ball (own frame) and when it was said; see {@link #teamBall}. */
    private final Vector2[] heardBalls = new Vector2[MAX_ID + 1];
    private final double[] heardTimes = new double[MAX_ID + 1];
    private final List<Vector2> heardRecent = new ArrayList<>(MAX_ID);
    private final BallFusion heardFusion;
    /** This cycle's fusion of the recent reports (null: none), and the newest report's time among them. */
    private Vector2 heardBall;
    private double heardTime = Double.NEGATIVE_INFINITY;
    /** Reports said before this time are void: their ball lay in view and was not there (heardMissed). */
    private double heardVoidBefore = Double.NEGATIVE_INFINITY;
    /** Steady vision frames in a row with the heard ball in view and no ball seen. */
    private int heardMisses;
    private List<PlayerBelief> mateList = List.of(), otherList = List.of();
    private WorldBelief belief;

    /**
     * @param teamName our team's name as sent in init (to tell teammates from opponents)
     * @param side     our side, or null to learn it from the first GS message
     * @param unum     our uniform number, or 0 to learn it from the first GS message
     */
    public BeliefStore(FieldSpec field, LocalizationConfig config, NaoModel body, String teamName, Side side, int unum) {
        this.field = field;
        this.config = config;
        this.body = body;
        this.teamName = teamName == null ? "" : teamName;
        this.side = side;
        this.unum = unum;
        localizer = new SelfLocalizer(field, config);
        selfFilter = config.filter() == LocalizationConfig.Filter.EKF ? new EkfPoseFilter(config) : new FifoPoseFilter(config);
        // Ours (session 19): the ball's queue relocates like the self filter's, after relocateFrames sightings in a row
        // that disagree with it and agree with each other (a kicked, rolling or replaced ball), instead of holding the old
        // place until MaxSize refusals have emptied it.
        ballFilter = new LocalizationFilter(config.fifoMaxSize(), config.ballAgreementMetres(), Double.NaN, config.relocateFrames(),
                config.ballAgreementMetres(), Double.NaN, config.relocateSpreadMetres(), Double.NaN);
        ballTracker = new MovingObjectTracker(config.trackSetSize(), config.trackDelay(), 1.0);
        fallDetector = new FallDetector(config);
        heardFusion = new BallFusion(config.fusionClusterMetres(), config.fusionWeightExponent());
        tilt = new TiltEstimator(config.accSmoothing(), STEADY_TOLERANCE);
        belief = snapshot(FallState.STANDING);
    }

    /**
     * The agent's own motion since the last call, in its body frame (metres forward and left,
     * degrees turned counter-clockwise), from the walk's odometry; applied at the next update.
     */
    public void odometry(double forward, double left, double turnDeg) {
        if (!Double.isFinite(forward) || !Double.isFinite(left) || !Double.isFinite(turnDeg)) return;
        odoForward += forward;
        odoLeft += left;
        odoTurn += turnDeg;
    }

    /**
     * A teammate's report of the ball (thesis 5.3's "C": his own sighting, in the own frame) and the server time it was
     * said. The reports heard within {@code teamBallMemorySeconds} are fused as the coordinator fuses them (thesis 5.4,
     * {@link BallFusion}), and the belief falls back on that ball while the own ball was last seen more than
     * {@code teamBallAfterSeconds} ago (issue 19). A heard ball that lies in view for ballMissFrames frames without being
     * seen voids the reports said so far, as an own ball would be dropped. Bad sender, null or non-finite: ignored.
     */
    public void teamBall(int sender, Vector2 ownFrame, double saidTime) {
        if (sender < 1 || sender > MAX_ID || ownFrame == null || !ownFrame.isFinite() || !Double.isFinite(saidTime)) return;
        heardBalls[sender] = ownFrame;
        heardTimes[sender] = saidTime;
    }

    /** Forgets the self and ball beliefs (for example after the agent was moved by a beam). */
    public void forgetPose() {
        selfFilter.reset();
        ballFilter.clear();
        ballTracker.clear();
        ballVx = ballVy = 0;
        selfTime = Double.NEGATIVE_INFINITY;
    }

    /**
     * The self belief was re-initialised: the filtered ball, its track and the last relative sighting
     * (taken before the move) are dropped; the next sighting is accepted wherever it is.
     */
    private void dropBall() {
        ballMisses = 0;
        ballFilter.clear();
        ballTracker.clear();
        ballVx = ballVy = 0;
        ballRelative = null;
        ballTime = Double.NEGATIVE_INFINITY;
    }

    /** One cycle: every perception the server sent, in order. Never throws on odd content. */
    public WorldBelief update(Perception p) {
        stats.cycles++;
        if (p == null) return belief;
        if (Double.isFinite(p.time())) time = p.time();
        GameState gs = p.gameState();
        if (gs != null) {
            if (gs.side() != null) side = gs.side();
            if (gs.unum() > 0 && unum == 0) unum = gs.unum();
        }
        FallState fall = fallDetector.update(p.acc(), p.gyro(), p.footForces());
        double dt = Double.isFinite(lastTime) && Double.isFinite(p.time()) ? p.time() - lastTime : CYCLE;
        lastTime = p.time();
        tilt.update(p.gyro(), p.acc(), dt);

        // The turn since the last cycle (issue 19): the gyro's about the vertical where there is a reading (config.gyroTurn),
        // else the odometry's. Upright, gyro z x dt matches the true yaw change of the same cycle to 0.008°/cycle rms
        // (turn-head, walk-head, crowd), where the walk's odometry commands 1.20°/cycle for 1.10 turned, and without
        // odometry the belief did not turn at all between fixes (turn-head: 61° behind, single landmarks then gated out).
        double rate = config.gyroTurn() ? tilt.turnRateDeg(p.gyro()) : Double.NaN;
        if (Double.isFinite(rate) && dt > 0 && dt < 0.5) odoTurn = rate * dt;
        selfFilter.predict(odoForward, odoLeft, odoTurn);
        if (ballRelative != null && (odoForward != 0 || odoLeft != 0 || odoTurn != 0)) {
            // ballRelative.minus(new Vector2(odoForward, odoLeft)).rotate(-odoTurn) in one allocation
            double x = ballRelative.x() - odoForward, y = ballRelative.y() - odoLeft;
            double r = Math.toRadians(-odoTurn), c = Math.cos(r), s = Math.sin(r);
            ballRelative = new Vector2(c * x - s * y, s * x + c * y);
        }
        odoForward = odoLeft = odoTurn = 0;
        if ((ballVx != 0 || ballVy != 0) && dt > 0 && dt < 0.5) {
            // The rolling ball (issue 19): its queued sightings move on with it, slowing as the server's drag does.
            ballFilter.translate(ballVx * dt, ballVy * dt);
            double decay = Math.exp(-config.ballDecayPerSecond() * dt);
            ballVx *= decay;
            ballVy *= decay;
        }

        fuseHeard();
        if (p.hasVision()) see(p, fall);
        else stats.noVision++;
        belief = snapshot(fall);
        if (belief.self() != null && (belief.ballHeard() || !(belief.ballAge() <= config.teamBallAfterSeconds()))) stats.staleBallCycles++;
        if (belief.ballHeard()) stats.heardBallCycles++;
        return belief;
    }

    public WorldBelief belief() { return belief; }

    /**
     * Whether a keyframe motion (get-up, kick, dive) moves the body this cycle. While it does, vision
     * places nothing: the tilt estimate lags such motions, and in games fixes taken while a keeper got up
     * put it metres away, once at the mirrored x (localization/README.md).
     */
    public void bodyBusy(boolean busy) { this.bodyBusy = busy; }

    public BeliefStats stats() { return stats; }

    /** The accelerometer reads about 1 g: the robot is not being thrown about. */
    private static boolean isSteady(Vector3 a) {
        if (a == null || !a.isFinite()) return true;     // no reading: trust the joints alone
        double n = a.norm();
        if (n < 1.0) return true;                         // no gravity reading yet (first messages)
        return n > 9.81 - STEADY_TOLERANCE && n < 9.81 + STEADY_TOLERANCE;
    }

    private void see(Perception p, FallState fall) {
        stats.visionFrames++;
        Vision v = p.vision();
        CameraPose camera = CameraPose.of(body, p.joints(), tilt.up());
        sightings.clear();
        for (int i = 0; i < Landmark.COUNT; i++) {
            Polar pol = v.landmarks()[i];
            if (pol == null) continue;
            if (!pol.isUsable()) { stats.badPolar++; continue; }
            if (side == null) continue;
            Landmark l = Landmark.byIndex(i);
            Vector3 at = field.landmark(l, side);
            sightings.add(new LandmarkSighting(l, new Vector2(at.x(), at.y()), camera.toGround(pol)));
        }
        if (side == null) stats.noSide++;
        else if (sightings.isEmpty()) stats.noLandmark++;
        else if (sightings.size() == 1) stats.oneLandmark++;

        // Lying or falling, or the accelerometer reading more than gravity: the tilt, hence the
        // camera pose, is unknown, and a fix would be wrong by metres (S3). Keep the old belief.
        boolean steady = fall == FallState.STANDING && !bodyBusy && isSteady(p.acc());
        if (!steady) {
            stats.fallenFrames++;
        } else if (side != null) {
            Pose2 fix = localizer.locate(sightings);
            if (fix != null) stats.selfFixes++;
            int starts = selfFilter.starts();
            if (selfFilter.update(fix, sightings)) {
                stats.selfUpdates++;
                selfTime = time;
            }
            // A new self belief (the first, a restart after the FIFO's queue emptied, a relocation
            // after a beam or trainer move): every ball position was placed with the old pose, or with
            // none, and is dropped; this frame's ball sighting then starts the ball belief afresh.
            // (Before issue 19 the ball was cleared only on a jump between two poses, which a FIFO
            // queue emptied by refusals never shows: S6 kept the old ball for 2.4 s.)
            if (selfFilter.starts() != starts) {
                stats.selfStarts++;
                if (selfStarted) dropBall();
                selfStarted = true;
            }
        }
        Pose2 self = selfFilter.pose();

        Polar ball = v.ball();
        if (ball == null && missed(camera, self, steady)) {
            stats.ballsMissed++;
            dropBall();
        }
        if (ball == null && heardMissed(camera, self, steady)) {
            stats.heardBallsMissed++;
            heardVoidBefore = time;
            heardBall = null;
        }
        if (ball != null) {
            ballMisses = 0;
            heardMisses = 0;
            if (!ball.isUsable()) stats.badPolar++;
            else {
                ballRelative = camera.toGround(ball);
                if (self != null && steady) {
                    Vector2 g = self.toGlobal(ballRelative);
                    // The belief is the queue's average: a sighting the queue refuses does not refresh it, or the old
                    // place would pass for seen just now and be looked at instead of the ball (session 19).
                    if (ballFilter.add(g)) ballTime = time;
                    ballTracker.observe(g, time);
                    rolling(g);
                } else {
                    ballTime = time;
                }
            }
        }
        boolean changed = false;
        for (SeenPlayer sp : v.players()) changed |= seePlayer(sp, camera, self);
        if (changed) {
            mateList = collect(mates);
            otherList = collect(others);
        }
    }

    /**
     * The velocity the ball queue moves by between sightings (issue 19, not in the thesis): Track Moving Object's, at
     * least {@code ballRollMinSpeed}, brought forward to now with the drag (it is the mean over the tracker's window,
     * centred {@link MovingObjectTracker#age} ago), and only while the last two sightings show the ball moving, at
     * least {@code ballRollMinSpeed} too and the same way (within {@code ballRollAgreeShare} of the speed plus
     * {@code ballRollAgreeMps}): a ball placed elsewhere shows a jump in the tracker's window and then no motion, and
     * would otherwise be carried on at the jump's speed. Else 0.
     */
    private void rolling(Vector2 g) {
        Vector2 v = ballTracker.velocity();
        boolean agrees = false;
        if (v != null && time > lastSeenTime) {
            double ix = (g.x() - lastSeenX) / (time - lastSeenTime), iy = (g.y() - lastSeenY) / (time - lastSeenTime);
            agrees = Math.hypot(ix, iy) >= config.ballRollMinSpeed()
                    && Math.hypot(ix - v.x(), iy - v.y()) <= config.ballRollAgreeShare() * v.norm() + config.ballRollAgreeMps();
        }
        lastSeenX = g.x();
        lastSeenY = g.y();
        lastSeenTime = time;
        if (agrees && v.norm() >= config.ballRollMinSpeed()) {
            double f = Math.exp(-config.ballDecayPerSecond() * ballTracker.age(time));
            ballVx = v.x() * f;
            ballVy = v.y() * f;
        } else {
            ballVx = ballVy = 0;
        }
    }

    /**
     * This frame saw no ball although the believed ball lies in the camera's view: the server reports every object in
     * its view cone (no occlusion), so after ballMissFrames such frames in a row the ball is not there (kicked past,
     * taken away) and the belief goes, instead of being looked at until it ages out (docs/matches.md, session 21).
     */
    private boolean missed(CameraPose camera, Pose2 self, boolean steady) {
        int frames = config.ballMissFrames();
        Vector2 ball = self == null ? null : ballFilter.position();
        if (frames <= 0 || !steady || ball == null) return false;
        if (!camera.inView(self.toRelative(ball), BALL_CENTRE_HEIGHT, config.ballMissViewDeg())) return false;
        if (++ballMisses < frames) return false;
        ballMisses = 0;
        return true;
    }

    /** The same rule as {@link #missed} for the teammates' ball while the belief falls back on it. */
    private boolean heardMissed(CameraPose camera, Pose2 self, boolean steady) {
        int frames = config.ballMissFrames();
        if (frames <= 0 || !steady || self == null || !usesHeardBall()) return false;
        if (!camera.inView(self.toRelative(heardBall), BALL_CENTRE_HEIGHT, config.ballMissViewDeg())) return false;
        if (++heardMisses < frames) return false;
        heardMisses = 0;
        return true;
    }

    /** This cycle's teammates' ball: the fusion of the reports said within the memory, after the last void. */
    private void fuseHeard() {
        heardRecent.clear();
        heardTime = Double.NEGATIVE_INFINITY;
        double now = Double.isNaN(time) ? 0 : time;
        // Only a stale own ball reads the reports: the fusion is not run in the ~98 % of cycles that would not use it.
        if (!(now - ballTime > config.teamBallAfterSeconds())) {
            heardBall = null;
            heardMisses = 0;
            return;
        }
        for (int u = 1; u <= MAX_ID; u++) {
            if (heardBalls[u] == null || heardTimes[u] < heardVoidBefore || now - heardTimes[u] > config.teamBallMemorySeconds()) continue;
            heardRecent.add(heardBalls[u]);
            heardTime = Math.max(heardTime, heardTimes[u]);
        }
        Vector2 fused = heardRecent.isEmpty() ? null : heardFusion.fuse(heardRecent);
        // a new report moves the fusion a little; only a ball believed elsewhere starts the miss count again
        if (fused == null || heardBall == null || fused.distanceTo(heardBall) > config.ballAgreementMetres()) heardMisses = 0;
        heardBall = fused;
    }

    /** The own ball is stale and a heard one is recent enough (and newer than the own sighting). */
    private boolean usesHeardBall() {
        double now = Double.isNaN(time) ? 0 : time;
        return heardBall != null && now - ballTime > config.teamBallAfterSeconds()
                && now - heardTime <= config.teamBallMemorySeconds() && heardTime > ballTime;
    }

    private boolean seePlayer(SeenPlayer sp, CameraPose camera, Pose2 self) {
        if (sp.id() <= 0 || sp.id() > MAX_ID) { stats.playerWithoutId++; return false; }
        boolean mate = teamName.equals(sp.team());
        if (mate && sp.id() == unum) return false;      // the agent sees its own lower arms
        Vector2[] rel = new Vector2[BodyPart.COUNT];
        double sx = 0, sy = 0;
        int n = 0;
        for (int i = 0; i < BodyPart.COUNT; i++) {
            Polar pol = sp.parts()[i];
            if (pol == null) continue;
            if (!pol.isUsable()) { stats.badPolar++; continue; }
            rel[i] = camera.toGround(pol);
            sx += rel[i].x();
            sy += rel[i].y();
            n++;
        }
        if (n == 0) return false;
        Vector2 head = rel[BodyPart.HEAD.ordinal()];
        Vector2 where = head != null ? head : new Vector2(sx / n, sy / n);
        PlayerBelief b = new PlayerBelief(sp.team(), sp.id(), time, where, self == null ? null : self.toGlobal(where), rel, self);
        (mate ? mates : others)[sp.id()] = b;
        return true;
    }

    private static List<PlayerBelief> collect(PlayerBelief[] byId) {
        List<PlayerBelief> l = new ArrayList<>();
        for (PlayerBelief b : byId) if (b != null) l.add(b);
        return List.copyOf(l);
    }

    private WorldBelief snapshot(FallState fall) {
        Pose2 self = selfFilter.pose();
        Vector2 ballGlobal = self == null ? null : ballFilter.position();
        Vector2 rel = ballRelative;
        // With a self belief the filtered ball is the better relative estimate too.
        if (ballGlobal != null) rel = self.toRelative(ballGlobal);
        double now = Double.isNaN(time) ? 0 : time;
        if (self != null && usesHeardBall()) {
            // The own ball is stale: the teammates' (issue 19, thesis 5.4). No velocity: a report carries none.
            return new WorldBelief(time, side, unum, self, selfFilter.confidence(), now - selfTime,
                    self.toRelative(heardBall), heardBall, now - heardTime, null, mateList, otherList, fall, true);
        }
        return new WorldBelief(time, side, unum, self, selfFilter.confidence(), now - selfTime,
                rel, ballGlobal, now - ballTime, ballGlobal == null ? null : ballTracker.velocity(),
                mateList, otherList, fall, false);
    }
}

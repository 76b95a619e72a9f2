package phalanx.bench.motion;

import java.util.List;

/**
 * What {@link TrialCheck#kick} needs from the pictures of one kick: how far the robot's body parts got from
 * where they were at the start (a robot that never moved is not the one kicking), how close any part's
 * centre came to the ball's centre, and how far the ball got from where it lay.
 */
final class KickWatch {
    private final List<double[]> parts0;
    private final double[] ball0;
    private double bodyTravel, closest = Double.POSITIVE_INFINITY, ballTravel;

    /** The robot's body part centres (null: not in the scene) and the ball ({x, y, z}) at the kick's start. */
    KickWatch(List<double[]> parts, double[] ball) {
        this.parts0 = parts;
        this.ball0 = ball;
    }

    /** One picture; either may be null (not in it, or not looked at). */
    void see(List<double[]> parts, double[] ball) {
        if (parts != null && parts0 != null) {
            for (int i = 0; i < Math.min(parts.size(), parts0.size()); i++) bodyTravel = Math.max(bodyTravel, dist(parts.get(i), parts0.get(i)));
        }
        if (ball != null) {
            ballTravel = Math.max(ballTravel, dist(ball, ball0));
            if (parts != null) for (double[] q : parts) closest = Math.min(closest, dist(q, ball));
        }
    }

    double bodyTravel() { return bodyTravel; }

    /** Closest approach of a body part's centre to the ball's centre (m); infinite when never seen together. */
    double closest() { return closest; }

    double ballTravel() { return ballTravel; }

    private static double dist(double[] a, double[] b) {
        return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
}

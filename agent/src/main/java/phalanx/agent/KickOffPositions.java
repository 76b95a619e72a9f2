package phalanx.agent;

/**
 * Where each player beams before kick-off (own half, own frame, facing the opponent's goal). The
 * 11-player spots are the ones the S5 recording used; the 9-player ones scale them to 21 x 14 m.
 * Replaced by the coordination's formation once the team plays (issue 8).
 */
final class KickOffPositions {
    private static final double[][] ELEVEN = {
            {-14, 0}, {-11, -5}, {-11.5, -1.5}, {-11.5, 1.5}, {-11, 5}, {-7, -3}, {-6, 0}, {-7, 3}, {-2.5, -6}, {-2.5, 6}, {-1, 0}};

    private KickOffPositions() {}

    /** {x, y} for uniform number 1..players. */
    static double[] of(int unum, int players) {
        if (unum < 1 || unum > players) return new double[]{-3, 0};
        double[] p = ELEVEN[unum - 1];
        if (players == 11) return p.clone();
        return new double[]{p[0] * 10.5 / 15, p[1] * 7 / 10.0};
    }
}

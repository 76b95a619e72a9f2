package phalanx.model.field;

import phalanx.comm.perception.Vector3;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A field of rcssservermj (rcsssmj 0.2.1, games/soccer/soccer_fields.py) and the named markers its vision
 * reports (games/soccer/sim/soccer_sim.py {@code _create_world}). World frame: origin at the centre spot,
 * +x towards the right goal; our own frame is this one for the left team and turned by 180° for the right.
 *
 * @param goalieArea  depth and width of the goalie area
 * @param penaltyArea depth and width of the penalty area
 * @param players     players per team on the rule book that uses this field
 */
public record MjField(String name, double length, double width, double goalWidth, double goalHeight,
                      double[] goalieArea, double[] penaltyArea, double centreRadius, double penaltySpot, int players) {

    /** FIFA 7 v 7, the field of the default rule book {@code ssim}: 7 players a side. */
    public static final MjField SSIM = new MjField("fifa7vs7", 55, 36, 3.66, 1.83,
            new double[] {4, 7.3}, new double[] {9, 16.5}, 5.5, 7.32, 7);

    /**
     * This field as the plane the SimSpark-side code works on (self-localization's geometry, the coordination's
     * field): its size, goal, penalty area as FieldSpec's penalty box, centre circle and team size.
     */
    public FieldSpec spec() {
        return new FieldSpec(name, length, width, goalWidth, goalHeight, penaltyArea[0], penaltyArea[1], centreRadius, players);
    }

    public double halfLength() { return length / 2; }
    public double halfWidth() { return width / 2; }

    /**
     * Every marker's world position. Server quirk (soccer_sim.py): the goalie- and penalty-area markers sit
     * at y = ±(the area's full width), not ±half of it as the area's lines do, e.g. l_luga at y = 7.3.
     */
    public Map<String, Vector3> markers() {
        double hx = halfLength(), hy = halfWidth(), gy = goalWidth / 2;
        double gax = hx - goalieArea[0], gay = goalieArea[1];
        double pax = hx - penaltyArea[0], pay = penaltyArea[1];
        double spot = hx - penaltySpot;
        Map<String, Vector3> m = new LinkedHashMap<>();
        put(m, "l_luf", -hx, hy, 0); put(m, "l_llf", -hx, -hy, 0); put(m, "l_ruf", hx, hy, 0); put(m, "l_rlf", hx, -hy, 0);
        put(m, "t_cuf", 0, hy, 0); put(m, "t_clf", 0, -hy, 0);
        put(m, "x_cuc", 0, centreRadius, 0); put(m, "x_clc", 0, -centreRadius, 0);
        put(m, "p_lpm", -spot, 0, 0); put(m, "p_rpm", spot, 0, 0);
        put(m, "g_lup", -hx, gy, goalHeight); put(m, "g_llp", -hx, -gy, goalHeight);
        put(m, "g_rup", hx, gy, goalHeight); put(m, "g_rlp", hx, -gy, goalHeight);
        put(m, "l_luga", -gax, gay, 0); put(m, "l_llga", -gax, -gay, 0); put(m, "l_ruga", gax, gay, 0); put(m, "l_rlga", gax, -gay, 0);
        put(m, "t_luga", -hx, gay, 0); put(m, "t_llga", -hx, -gay, 0); put(m, "t_ruga", hx, gay, 0); put(m, "t_rlga", hx, -gay, 0);
        put(m, "l_lupa", -pax, pay, 0); put(m, "l_llpa", -pax, -pay, 0); put(m, "l_rupa", pax, pay, 0); put(m, "l_rlpa", pax, -pay, 0);
        put(m, "t_lupa", -hx, pay, 0); put(m, "t_llpa", -hx, -pay, 0); put(m, "t_rupa", hx, pay, 0); put(m, "t_rlpa", hx, -pay, 0);
        return m;
    }

    private static void put(Map<String, Vector3> m, String name, double x, double y, double z) {
        m.put(name, new Vector3(x, y, z));
    }
}

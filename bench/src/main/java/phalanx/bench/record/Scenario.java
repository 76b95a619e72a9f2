package phalanx.bench.record;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The situations the recorder stages (issue 19), each written in the recorded team's own frame (attacking +x):
 * for a recording on the right side the other team's beams and the trainer's positions and velocities are turned
 * by 180° into the field frame. The recorded robot is player 1 of team {@link #RECORDED_TEAM}; the others are
 * robots of our own code standing, turning or walking (opponents of team {@code Crowd}, or a {@code Dummy}, which
 * also takes the left side when the recorded robot is to be on the right).
 */
record Scenario(String name, String about, int defaultType, Plan recorded, List<Member> others, Map<Integer, List<String>> trainer) {
    static final String RECORDED_TEAM = "Probe";

    /** Another robot: team, unum, type, plan (its beam in the recorded team's own frame). */
    record Member(String team, int unum, int type, Plan plan) {}

    static final List<String> NAMES = List.of("walk-head", "turn-head", "ball-roll", "crowd", "fall");

    /** The scenario; {@code right}: the recorded robot plays on the right (the trainer's commands are mirrored). */
    static Scenario of(String name, boolean right) {
        Trainer t = new Trainer(right);
        List<Member> others = new ArrayList<>();
        Plan rec;
        String about;
        int type;
        switch (name) {
            case "walk-head" -> {
                // the first case: the head tilts up and down and pans while the robot walks and turns
                type = 0;
                about = "walks, turns in place, walks a curve, turns back, walks; head pans ±90° (4 s) and tilts -10±35° (2.6 s)";
                rec = Plan.at(-9, 2, 0).pan(90, 4).tilt(-10, 35, 2.6)
                        .stand(1).walk(5, 0.6, 0, 0).walk(4, 0, 0, 60).walk(5, 0.4, 0, 25).walk(4, 0, 0, -60).walk(4, 0.6, 0, 0).stand(1.5).build();
                others.add(new Member("Dummy", 1, 0, Plan.at(12, -6, 180).stand(1).build()));
                t.at(30, "(playMode PlayOn)");
            }
            case "turn-head" -> {
                // the first case again, turning: the head sweeps fast while the robot turns in place both ways
                type = 1;
                about = "turns in place left 6 s, stands, turns right 6 s, side-steps left 3 s, turns left 4 s; head pans ±100° (3 s) and tilts -20±25° (2 s)";
                rec = Plan.at(-3, -3, 45).pan(100, 3).tilt(-20, 25, 2)
                        .stand(1).walk(6, 0, 0, 60).stand(1).walk(6, 0, 0, -60).walk(3, 0, 0.3, 0).walk(4, 0, 0, 60).stand(1).build();
                others.add(new Member("Dummy", 1, 0, Plan.at(12, -6, 180).stand(1).build()));
                t.at(30, "(playMode PlayOn)");
                t.ball(32, 2, -1, 0, 0);
            }
            case "ball-roll" -> {
                // balls rolled across the view, past the robot from behind and toward it, as kicks do (ball decay 1.06/s)
                type = 1;
                about = "stands, head pans ±60° (6 s); the trainer rolls the ball across 4 m ahead, diagonally in front, past it from behind, toward it";
                rec = Plan.at(-4, 0, 0).pan(60, 6).tilt(-15, 10, 3).stand(26).build();
                others.add(new Member("Dummy", 1, 0, Plan.at(12, -6, 180).stand(1).build()));
                t.at(30, "(playMode PlayOn)");
                t.ball(100, 0, -5, 0, 7);
                t.ball(400, -1, 3, -2.2, -5.5);
                t.ball(700, -6, 0.5, 6, 0);
                t.ball(1000, 1, -1.5, -6, 0.3);
            }
            case "crowd" -> {
                // six opponents of our own code round the ball, standing, turning and stepping; the robot walks up to them
                type = 2;
                about = "six opponents (types 0-4) round the ball at (1.5, 0), turning and stepping; the robot walks toward them, turns, walks; head pans ±70° (5 s), tilts -15±15° (3 s)";
                rec = Plan.at(-3, 0.5, 0).pan(70, 5).tilt(-15, 15, 3)
                        .stand(2).walk(4, 0.3, 0, 0).stand(4).walk(3, 0, 0, 40).walk(3, 0, 0, -40).walk(3, 0.3, 0, 0).stand(5).build();
                double[][] spots = {{1.0, 0.6}, {1.2, -0.7}, {2.1, 0.2}, {1.6, 1.3}, {2.4, -1.0}, {0.9, -1.6}};
                int[] types = {0, 1, 2, 3, 4, 0};
                for (int i = 0; i < spots.length; i++) {
                    Plan.Builder b = Plan.at(spots[i][0], spots[i][1], 180).pan(40 + 10 * i, 3 + i);
                    if (i % 2 == 0) b.stand(2 + i).walk(3, 0, 0, i % 4 == 0 ? 30 : -30).stand(2).walk(4, 0.15, 0, 10);
                    else b.walk(3, 0.1, 0, 0).stand(3).walk(3, 0, 0, -25);
                    others.add(new Member("Crowd", i + 1, types[i], b.build()));
                }
                t.at(30, "(playMode PlayOn)");
                t.ball(32, 1.5, 0, 0, 0);
                t.ball(700, 1.3, 0.3, 0, 0);
            }
            case "fall" -> {
                // falls on the back and on the front while walking, lies, gets up (the agent's get-ups), walks on
                type = 3;
                about = "walks, tips backwards (ankles -2 rad/s), lies 1.5 s, gets up, walks, tips forwards (+2 rad/s), lies, gets up, turns; head pans ±45° (4 s)";
                rec = Plan.at(-6, -2, 30).pan(45, 4)
                        .stand(1).walk(3, 0.5, 0, 0).tip(-2).stand(1.5).getUp().stand(1)
                        .walk(3, 0.5, 0, 0).tip(2).stand(1.5).getUp().stand(1).walk(3, 0, 0, 50).stand(1).build();
                others.add(new Member("Dummy", 1, 0, Plan.at(12, -6, 180).stand(1).build()));
                t.at(30, "(playMode PlayOn)");
            }
            default -> throw new IllegalArgumentException("unknown scenario '" + name + "' (one of " + String.join(", ", NAMES) + ")");
        }
        // the other team's own frame (its beams) is the recorded team's turned by 180°, on either side
        List<Member> turned = new ArrayList<>();
        for (Member m : others) {
            Plan p = m.plan();
            turned.add(new Member(m.team(), m.unum(), m.type(), new Plan(-p.beamX(), -p.beamY(), p.beamDeg() - 180, p.steps(),
                    p.panDeg(), p.panS(), p.tiltMidDeg(), p.tiltDeg(), p.tiltS())));
        }
        return new Scenario(name, about, type, rec, List.copyOf(turned), t.commands());
    }

    /** Trainer commands by the recorded robot's message count, in the field frame. */
    static final class Trainer {
        private final boolean mirror;
        private final Map<Integer, List<String>> at = new TreeMap<>();

        Trainer(boolean mirror) { this.mirror = mirror; }

        void at(int k, String command) { at.computeIfAbsent(k, x -> new ArrayList<>()).add(command); }

        /** The ball put at (x, y) of the recorded team's frame, rolling at (vx, vy) m/s. */
        void ball(int k, double x, double y, double vx, double vy) {
            double s = mirror ? -1 : 1;
            at(k, String.format(Locale.ROOT, "(ball (pos %s %s 0.042) (vel %s %s 0))", n(s * x), n(s * y), n(s * vx), n(s * vy)));
        }

        private static String n(double v) {
            String s = String.format(Locale.ROOT, "%.3f", v + 0.0).replaceAll("0+$", "");
            return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
        }

        Map<Integer, List<String>> commands() { return at; }
    }
}

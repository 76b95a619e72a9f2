package phalanx.agent.roboviz;

import phalanx.comm.perception.Side;
import phalanx.localization.belief.PlayerBelief;
import phalanx.localization.belief.WorldBelief;
import phalanx.model.field.Pose2;
import phalanx.model.field.Vector2;

/**
 * Draws one player's beliefs into RoboViz, one set per layer under
 * {@code animated.phalanx.<team>.<unum>}: self (circle and heading), ball, teammates, opponents,
 * target; then swaps that prefix once. Beliefs are in the team's own frame; RoboViz draws in the
 * field frame, so a right-side team's points are turned by 180°.
 */
public final class BeliefDrawing {
    private static final int SELF = 0x00c0ff, BALL = 0xff8000, MATE = 0x40ff40, OPPONENT = 0xff3030, TARGET = 0xffff00;

    private BeliefDrawing() {}

    public static void draw(RoboViz rv, WorldBelief b, Vector2 target, String team, int unum) {
        String prefix = "animated.phalanx." + team + "." + unum;
        int flip = b.side() == Side.RIGHT ? -1 : 1;
        Pose2 self = b.self();
        if (self != null) {
            Vector2 head = self.position().plus(Vector2.ofAngle(self.thetaDeg()).times(0.4));
            rv.circle(flip * self.x(), flip * self.y(), 0.2, 2, SELF, prefix + ".self")
              .line(flip * self.x(), flip * self.y(), 0.02, flip * head.x(), flip * head.y(), 0.02, 2, SELF, prefix + ".self");
        }
        if (b.ballGlobal() != null) rv.sphere(flip * b.ballGlobal().x(), flip * b.ballGlobal().y(), 0.042, 0.06, BALL, prefix + ".ball");
        for (PlayerBelief p : b.teammates()) dot(rv, p, flip, MATE, prefix + ".teammates");
        for (PlayerBelief p : b.opponents()) dot(rv, p, flip, OPPONENT, prefix + ".opponents");
        if (target != null && self != null) {
            rv.line(flip * self.x(), flip * self.y(), 0.02, flip * target.x(), flip * target.y(), 0.02, 1, TARGET, prefix + ".target");
        }
        rv.swap(prefix);
        rv.flush();
    }

    private static void dot(RoboViz rv, PlayerBelief p, int flip, int rgb, String set) {
        if (p.global() != null) rv.point(flip * p.global().x(), flip * p.global().y(), 0.3, 6, rgb, set);
    }
}

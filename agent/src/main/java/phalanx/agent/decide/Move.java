package phalanx.agent.decide;

/**
 * What the body should do this cycle, said in the terms of thesis 4.6 rather than motion file
 * names: {@code act.Locomotion} turns it into the motion controller's request, so the actions
 * do not change when the walk does.
 */
public sealed interface Move {
    /** Stand still (finish the playing motion and hold). */
    record Stand() implements Move {}

    /**
     * Walk forward. {@code lean} -1 (right) .. 1 (left) curves the path (Walk Leaning, 4.5.5);
     * {@code slow} shortens the steps near a target (Walk Slowdown).
     */
    record Walk(double lean, boolean slow) implements Move {
        public Walk {
            if (!Double.isFinite(lean)) lean = 0; // a bad belief must not reach the motion layer
        }
    }

    /** Turn in place; {@code left} chooses the side, {@code gain} 0.3-1.0 the speed (Turn Gain, 4.5.5). */
    record Turn(boolean left, double gain) implements Move {
        public Turn {
            if (!Double.isFinite(gain)) gain = 1;
        }
    }

    /**
     * Walk in any direction while turning (the omnidirectional walk, ours): each part a share -1 .. 1 of the
     * walk's limit (forward: + forward, - backward; left: + left; turn: + counter-clockwise).
     */
    record Omni(double forward, double left, double turn) implements Move {
        public Omni {
            forward = share(forward);
            left = share(left);
            turn = share(turn);
        }

        private static double share(double v) { return Double.isFinite(v) ? Math.max(-1, Math.min(1, v)) : 0; }
    }

    /** One side step. */
    record SideStep(boolean left) implements Move {}

    /** Small steps backward (Prepare For Kick, when the ball lies too close to the feet to kick). */
    record StepBack() implements Move {}

    /**
     * Kick with the right foot, or the left one if {@code left} (the ball in front of that foot: Prepare
     * for Kick); {@code strong} for the strong kick, {@code quick} for the quick kick (0.9 s, played without the
     * stand before it: motions/README.md).
     */
    record Kick(boolean strong, boolean left, boolean quick) implements Move {
        public Kick(boolean strong, boolean left) { this(strong, left, false); }
    }

    /** Get up; {@code fromFront} when lying face down. */
    record StandUp(boolean fromFront) implements Move {}

    /** The goalkeeper's dive to one side. */
    record Dive(boolean left) implements Move {}

    Move STAND = new Stand();
}

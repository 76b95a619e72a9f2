package phalanx.motion.phase;

import phalanx.motion.Motion;

import java.util.List;

/**
 * An XML phase motion (4.5.1): phases linked by next and finalize, starting at {@link #first()}.
 * Built only by {@link PhaseMotionLoader}, which guarantees every link points at a phase, every
 * duration is positive, and that following finalize links (else next) from any phase ends.
 */
public record PhaseMotion(String name, String source, List<Phase> phases, int first) implements Motion {
    public PhaseMotion {
        phases = List.copyOf(phases);
        if (first < 0 || first >= phases.size()) throw new IllegalArgumentException("first phase index out of range: " + first);
    }

    public Phase phase(int i) { return phases.get(i); }

    public int indexOf(String phaseName) {
        for (int i = 0; i < phases.size(); i++) if (phases.get(i).name().equals(phaseName)) return i;
        return -1;
    }
}

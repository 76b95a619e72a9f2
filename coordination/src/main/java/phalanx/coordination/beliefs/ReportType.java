package phalanx.coordination.beliefs;

/** The four coordination-message subtypes of thesis 5.3. */
public enum ReportType {
    /** Complete: own pose and the ball, both in the team's frame. */
    C,
    /** Located: own pose only (the ball is not in view). */
    L,
    /** Ball only, relative to the body: distance and bearing. */
    B,
    /** Neither: lost, or fallen. */
    X
}

package phalanx.comm.perception;

/** A visible field-line segment: its two end points as seen from the camera. */
public record SeenLine(Polar start, Polar end) {
}

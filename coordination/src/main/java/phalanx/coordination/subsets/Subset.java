package phalanx.coordination.subsets;

/** The four coordination subsets of thesis 5.5. */
public enum Subset { GOALKEEPER, INACTIVE, ACTIVE, SUPPORT }

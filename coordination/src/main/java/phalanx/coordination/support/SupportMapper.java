package phalanx.coordination.support;

/** Phase 6 of Algorithm 3, "Coordinate Support Players": maps every support player to one support position. */
public interface SupportMapper {
    SupportMapping map(SupportCost cost);
}

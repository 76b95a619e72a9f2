package phalanx.coordination.support;

/**
 * A mapping of support players to support positions.
 *
 * @param positionOf position index per player
 * @param cost       its {@link SupportCost}
 * @param evaluated  how many (partial) mappings the mapper scored; 0 for mappers that score none
 */
public record SupportMapping(int[] positionOf, double cost, long evaluated) {}

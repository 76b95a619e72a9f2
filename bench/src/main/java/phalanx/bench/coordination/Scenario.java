package phalanx.bench.coordination;

import phalanx.coordination.Memory;
import phalanx.coordination.Mode;
import phalanx.coordination.beliefs.TeamBeliefs;

/**
 * One coordination input read from a scenario file ({@link ScenarioFile}).
 *
 * @param name    where it came from, for titles and messages
 * @param beliefs the reports
 * @param mode    the coordination mode
 * @param memory  the previous round's on-ball player and ball
 * @param mapper  "dp" (Algorithm 5) or "scram"
 */
public record Scenario(String name, TeamBeliefs beliefs, Mode mode, Memory memory, String mapper) {}

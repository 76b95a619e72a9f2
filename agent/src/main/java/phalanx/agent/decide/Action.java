package phalanx.agent.decide;

/**
 * One behaviour of thesis 4.6 (basic or complex). Called once a cycle while it is the active one;
 * it may keep state between cycles (the On Ball state machine does). Values in, values out: no
 * socket, no clock but the situation's.
 */
public interface Action {
    Decision decide(Situation s);

    /** True when the action has reached its goal (a target reached, a kick done); the default never ends. */
    default boolean done(Situation s) { return false; }
}

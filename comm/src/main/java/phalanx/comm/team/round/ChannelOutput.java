package phalanx.comm.team.round;

import java.util.List;

/** One step's result: the text to say this cycle (null for nothing) and what happened. */
public record ChannelOutput(String say, List<ChannelEvent> events) {
    static final ChannelOutput NOTHING = new ChannelOutput(null, List.of());

    public ChannelOutput {
        events = events == null ? List.of() : List.copyOf(events);
    }
}

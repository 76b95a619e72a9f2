package phalanx.comm.team;

import java.util.Collection;
import java.util.List;

/**
 * What the round state machines ({@code phalanx.comm.team.round}) need of a team codec, so the same rounds run on
 * both servers: a message as the text of one say, a heard text back as a message, and a dispatch packed into as
 * many action messages as that server's say needs. {@link TeamMessageCodec} is SimSpark's (20 characters);
 * {@link MjTeamMessageCodec#text()} rcssservermj's (one 10-byte frame, as the base64 text the say carries).
 */
public interface SayCodec {
    /** The text to say for this message in the reply to the perception of {@code saidCycle}; refuses what cannot be sent. */
    String encode(TeamMessage message, long saidCycle);

    /** Our message in this text heard in the perception of {@code heardCycle}, or why it is not one. Never throws. */
    TeamMessageCodec.Decoded decode(String text, long heardCycle);

    /** One dispatch in as few action messages as fit, each telling how many follow. */
    List<TeamMessage.Actions> packActions(Collection<Action> actions);
}

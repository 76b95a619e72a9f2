/**
 * The team channel's transport (thesis 4.7, 5.3): the messages as values ({@link
 * phalanx.comm.team.TeamMessage}), their 20-character codec with its keyed check ({@link
 * phalanx.comm.team.TeamMessageCodec}, {@link phalanx.comm.team.SipHash}, {@link
 * phalanx.comm.team.TeamKey}), the labelled time slices ({@link phalanx.comm.team.TimeSlices}), the hear
 * side's checks ({@link phalanx.comm.team.Listener}) and every constant ({@link
 * phalanx.comm.team.ChannelConfig}). The rounds built on them are in {@code phalanx.comm.team.round}.
 */
package phalanx.comm.team;

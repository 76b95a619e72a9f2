/**
 * The team channel's rounds (thesis 5.3), the one owner of the round logic: {@link
 * phalanx.comm.team.round.CoordinatorRounds} on the goalkeeper (announce, gather reports, dispatch
 * actions) and {@link phalanx.comm.team.round.FieldPlayerRounds} on the others (announce, report in
 * its slot, follow the last order), with what they exchange with the player ({@link
 * phalanx.comm.team.round.ChannelOutput}, {@link phalanx.comm.team.round.ChannelEvent}, {@link
 * phalanx.comm.team.round.RoundReports}, {@link phalanx.comm.team.round.CoordinationProcedure}).
 * The transport they stand on (message codec, key, time slices, hear checks) is {@code phalanx.comm.team}.
 * State machines stepped once a cycle: no clock, no socket.
 */
package phalanx.comm.team.round;

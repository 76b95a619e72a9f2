package phalanx.agent;

import phalanx.comm.team.ChannelConfig;
import phalanx.coordination.CoordinationConfig;
import phalanx.localization.LocalizationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.robot.NaoModel;
import phalanx.motion.MotionConfig;
import phalanx.motion.walk.WalkConfig;

/**
 * Every module's config for one player, made in one place ({@link #of}) from the command line and the
 * robot type. Each part defaults to its module's value (the thesis's, or ours where we measured better;
 * each config's comment gives the section), so a change to how a player is configured is made here.
 *
 * @param field        the field of the server version (9 or 11 players)
 * @param body         the robot type's lengths (localization's camera height and odometry, the walk's kinematics)
 * @param localization beliefs and filters (localization)
 * @param motion       the keyframe and walk controllers' shared constants (motion)
 * @param walk         the walk, tuned per robot type (motion)
 * @param channel      the team channel (comm.team)
 * @param coordination the goalkeeper's team plan, also the formation field players fall back on (coordination)
 * @param agent        behaviours and actions, per robot type, with the command line's choices (agent)
 */
public record PlayerConfig(FieldSpec field, NaoModel body, LocalizationConfig localization, MotionConfig motion,
                           WalkConfig walk, ChannelConfig channel, CoordinationConfig coordination, AgentConfig agent) {

    /** The config a player started with these options plays with. */
    public static PlayerConfig of(PlayerOptions o) {
        AgentConfig agent = AgentConfig.forRobotType(o.robotType());
        return new PlayerConfig(FieldSpec.forPlayers(o.players()), NaoModel.ofType(o.robotType()),
                LocalizationConfig.DEFAULT, MotionConfig.DEFAULT.withStand(o.standBeforeMillis() / 1000.0, o.standAfterMillis() / 1000.0), WalkConfig.forType(o.robotType()),
                ChannelConfig.DEFAULT.withPlayers(o.players()), CoordinationConfig.THESIS,
                agent.withKick(agent.kick().withDribbleWithin(o.dribbleWithin()))
                        .withApproach(o.thesisApproach() ? AgentConfig.Approach.THESIS : agent.approach())
                        .withKickOff(o.kickOffKick() ? agent.kickOff() : AgentConfig.KickOff.TAP));
    }
}

package phalanx.agent;

import phalanx.agent.decide.Situation;
import phalanx.agent.roboviz.RoboViz;
import phalanx.agent.team.TeamChannel;
import phalanx.localization.belief.BeliefStore;
import phalanx.model.field.FieldSpec;
import phalanx.agent.act.Body;
import phalanx.motion.control.MotionController;

import phalanx.comm.perception.PlayMode;

import java.util.function.BiFunction;

/**
 * What one player is made of: its config, belief store, motion controller, field and debug drawer, and
 * its role (team channel end and brain), which depends on the uniform number and is made once the
 * number is known (the server may choose it).
 */
public final class PlayerParts {
    /** The role-dependent parts: the goalkeeper coordinates, the others are coordinated. */
    public record Role(TeamChannel channel, Brain brain) {}

    private final PlayerConfig config;
    private final BeliefStore beliefs;
    private final Body body;
    private final RoboViz draw;
    private final BiFunction<Integer, PlayerParts, Role> roleFactory;
    private Role role;
    private int roleUnum;
    private PlayMode playMode = PlayMode.BEFORE_KICK_OFF;

    public PlayerParts(PlayerConfig config, BeliefStore beliefs, Body body, RoboViz draw,
                       BiFunction<Integer, PlayerParts, Role> roleFactory) {
        this.config = config;
        this.beliefs = beliefs;
        this.body = body;
        this.draw = draw;
        this.roleFactory = roleFactory;
    }

    public BeliefStore beliefs() { return beliefs; }
    public Body body() { return body; }
    public PlayerConfig config() { return config; }
    public FieldSpec field() { return config.field(); }
    public RoboViz draw() { return draw; }

    /** The play mode of the latest message (the think loop keeps it current). */
    public PlayMode playMode() { return playMode; }

    void playMode(PlayMode mode) { if (mode != null) playMode = mode; }

    Situation.MotionStatus motionStatus() {
        MotionController k = body.keyframes();
        return new Situation.MotionStatus(k.playing(), k.lastCompleted(), k.completions());
    }

    /** The role for this uniform number, made on first use; null while the number is unknown (0). */
    Role role(int unum) {
        if (unum < 1) return null;
        if (role == null || roleUnum != unum) {
            role = roleFactory.apply(unum, this);
            roleUnum = unum;
        }
        return role;
    }
}

package phalanx.agent.mj;

import phalanx.agent.PlayerOptions;
import phalanx.comm.mj.MjActions;
import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.ServerConnection;
import phalanx.comm.wire.WireException;
import phalanx.model.field.MjField;

import java.io.IOException;
import java.util.logging.Logger;

/**
 * A player process on rcssservermj ({@code --server mj}): connects, sends {@code (init T1 team n)}, and answers
 * every message through {@link MjRuntime}. Exit status as {@code Player}: 0 when the connection ended after GameOver,
 * 1 when it was lost before, 2 for a number beyond the rule book's team, 3 when no server answered.
 */
public final class MjPlayer {
    private static final Logger LOG = Logger.getLogger(MjPlayer.class.getName());

    private MjPlayer() {}

    /** How a run ended. */
    public record Outcome(int status, String reason, long cycles, long malformed) {}

    public static int run(PlayerOptions o) {
        MjField field = MjField.SSIM;
        int unum = o.unum() == 0 ? 1 : o.unum();
        if (unum > field.players()) {
            System.err.println("phalanx-player: --unum " + unum + " is more than the " + field.players() + " players of rcssservermj's "
                    + field.name() + " rule book");
            return 2;
        }
        MjRuntime runtime;
        try {
            runtime = new MjRuntime(o.team(), unum, field, phalanx.agent.Player.teamKey(o.team()), o.motions().resolve("t1"));
        } catch (phalanx.motion.MotionFileException e) {
            System.err.println("phalanx-player: bad motion file: " + e.getMessage());
            return 2;
        }
        Outcome out = play(o, runtime);
        String msg = "phalanx-player " + o.unum() + " (mj): " + out.reason() + " after " + out.cycles() + " cycles ("
                + out.malformed() + " malformed messages skipped; " + runtime.getUps() + " get-ups, " + runtime.getUpRetries()
                + " of them retries; " + runtime.kicks() + " kicks; " + runtime.refereeMoves() + " moves by the referee; "
                + runtime.touchBars() + " double-touch bars; " + channel(runtime) + ")";
        LOG.info(msg);
        System.err.println(msg);
        return out.status();
    }

    /** The team channel's figures for the exit line: the coordinator's rounds, a field player's orders. */
    private static String channel(MjRuntime r) {
        var c = r.channel();
        return r.unum() == phalanx.comm.team.ChannelConfig.MJ.coordinator() ? c.rounds() + " coordination rounds (" + c.reportsInRounds() + " reports heard, " + c.actionsDispatched()
                + " actions sent)" : c.actionsReceived() + " orders received";
    }

    /** Plays until the connection ends or the game is over; never throws for bad input. */
    public static Outcome play(PlayerOptions o, MjRuntime runtime) {
        ServerConnection c;
        try {
            c = ServerConnection.connect(o.host(), o.port(), o.connectTimeoutMillis(), MjActions.init(o.team(), runtime.unum()));
        } catch (WireException e) {
            return new Outcome(3, e.getMessage() + " (is rcssservermj running? see docs/rcssservermj.md)", 0, 0);
        }
        try (c) {
            FrameReader in = c.reader();
            while (true) {
                in.next();
                c.send(runtime.update(in.text()));
                if (runtime.cycles() == 1) LOG.info("in the game as " + o.team() + " " + runtime.unum() + " (T1 on rcssservermj)");
            }
        } catch (ConnectionClosedException e) {
            return end(runtime, "server closed the connection: " + e.getMessage());
        } catch (IOException e) {
            return end(runtime, "connection lost: " + e.getMessage());
        }
    }

    private static Outcome end(MjRuntime r, String reason) {
        return new Outcome(r.world().playMode().equals("GameOver") ? 0 : 1, reason, r.cycles(), r.malformed());
    }
}

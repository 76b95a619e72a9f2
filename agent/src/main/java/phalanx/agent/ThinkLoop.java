package phalanx.agent;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Perception;
import phalanx.comm.sexp.MalformedMessageException;
import phalanx.comm.sexp.PerceptionParser;
import phalanx.comm.wire.ConnectionClosedException;
import phalanx.comm.wire.FrameReader;
import phalanx.comm.wire.ServerConnection;

import java.io.IOException;
import java.util.logging.Logger;

/**
 * The player's cycle: receive, parse, think, send the effectors and {@code (syn)} — every cycle
 * without fail, also when a message is malformed (logged and skipped: the server still needs the
 * syn). The first message after {@code (scene)} is answered with {@code (init)}.
 */
public final class ThinkLoop {
    private static final Logger LOG = Logger.getLogger(ThinkLoop.class.getName());

    /** How the loop ended. */
    public record Outcome(long cycles, long malformed, String reason) {}

    private final ServerConnection connection;
    private final PlayerOptions options;
    private final Behaviour behaviour;
    private final PerceptionParser parser = new PerceptionParser();
    private final EffectorMessage out = new EffectorMessage();

    public ThinkLoop(ServerConnection connection, PlayerOptions options, Behaviour behaviour) {
        this.connection = connection;
        this.options = options;
        this.behaviour = behaviour;
    }

    /** Runs until the connection ends; never throws for bad input. */
    public Outcome run() {
        long cycles = 0, malformed = 0;
        FrameReader in = connection.reader();
        try {
            connection.send(EffectorMessage.scene(options.robotType()));
            while (true) {
                in.next();
                cycles++;
                out.reset();
                if (cycles == 1) {
                    connection.send(EffectorMessage.init(options.unum(), options.team()));
                    continue;
                }
                if (cycles == 2) LOG.info("in the game as " + options.team() + " " + options.unum());
                Perception p;
                try {
                    p = parser.parse(in.buffer(), 0, in.length());
                } catch (MalformedMessageException e) {
                    malformed++;
                    if (malformed <= 10 || malformed % 1000 == 0) {
                        LOG.warning("cycle " + cycles + ": malformed message skipped (" + e.getMessage() + ")");
                    }
                    connection.send(out.syn().text());
                    continue;
                }
                try {
                    behaviour.think(p, out);
                } catch (RuntimeException e) {
                    // A bug in one decision must not cost the connection: log it and stand still this cycle.
                    LOG.severe("cycle " + cycles + ": behaviour failed: " + e);
                    out.reset();
                }
                connection.send(out.syn().text());
            }
        } catch (ConnectionClosedException e) {
            return new Outcome(cycles, malformed, "server closed the connection: " + e.getMessage());
        } catch (IOException e) {
            return new Outcome(cycles, malformed, "connection lost: " + e.getMessage());
        }
    }
}

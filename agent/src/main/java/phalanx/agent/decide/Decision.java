package phalanx.agent.decide;

import phalanx.model.field.Pose2;

/**
 * One cycle's decision: the body's move, where the head looks, and a beam (own frame; null for
 * none). The think loop carries it out.
 */
public record Decision(Move move, HeadTarget head, Pose2 beam) {

    public Decision {
        if (move == null) move = Move.STAND;
        if (head == null) head = HeadTarget.STRAIGHT;
    }

    public static Decision of(Move move, HeadTarget head) { return new Decision(move, head, null); }

    public Decision withHead(HeadTarget h) { return new Decision(move, h, beam); }

    public Decision withBeam(Pose2 b) { return new Decision(move, head, b); }
}

package phalanx.comm.team;

import phalanx.comm.team.round.FieldPlayerRounds;
import phalanx.comm.team.round.CoordinatorRounds;
import phalanx.comm.team.round.CoordinationProcedure;
import phalanx.comm.team.round.ChannelOutput;
import phalanx.comm.team.round.ChannelEvent;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.PlayMode;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;

/**
 * Eleven of our players (a {@link CoordinatorRounds} and ten {@link FieldPlayerRounds}s) talking through a
 * {@link SimulatedServer}, optionally with eleven opponents talking too. Deterministic (seeded).
 * Measures, per round: the cycles until the coordinator has every report, and until the last field
 * player has heard its action. A SIMULATION of the server's rules, not a measurement in rcssserver3d.
 *
 * <p>Run: {@code gradle -q :comm:teamChannelSimulation}.
 */
final class ChannelSimulation {

    enum Opponents {
        /** No opponent team. */
        NONE,
        /** Eleven opponents each say a random 20-character message every cycle. */
        RANDOM,
        /** Eleven opponents re-say, as soon as they can, the last message of ours they heard; random otherwise. */
        REPLAY
    }

    /** Formation beams of S5 (recordings README), our own frame; opponents mirrored. */
    static final double[][] FORMATION = {{-14, 0}, {-11, -5}, {-11.5, -1.5}, {-11.5, 1.5}, {-11, 5},
            {-7, -3}, {-6, 0}, {-7, 3}, {-2.5, -6}, {-2.5, 6}, {-1, 0}};
    static final String TEAM = "Phalanx", OPPONENT = "Rival";
    static final double BALL_X = -3, BALL_Y = 1;

    record Round(int round, long start, long reportsComplete, int reportsHeard, long lastActionHeard, int actionsHeard) {
        long hearAll() { return reportsComplete - start; }

        long fullRound() { return lastActionHeard - start; }
    }

    record Result(long startSaid, List<Round> rounds, int wrongReports, int wrongActions, long rejected) {
        Round first() { return rounds.get(0); }

        /** Rounds after the first, which start without an "s" message. */
        List<Round> steady() { return rounds.subList(1, rounds.size()); }
    }

    ChannelConfig config = ChannelConfig.DEFAULT;
    Opponents opponents = Opponents.NONE;
    boolean labelled = true;
    int latency = 2;
    /** Cycles between two of our players connecting (DESIGN: a few cycles apart). */
    int connectEvery = 3;
    Set<Integer> absent = Set.of();
    long seed = 1;

    Result run(int cycles) {
        TeamKey key = TeamKey.fromSecret("simulation-key-0123456789");
        SimulatedServer server = new SimulatedServer(latency, labelled);
        Random random = new Random(seed);
        int n = config.players();
        Map<Integer, Action> expected = new HashMap<>();
        int[] wrongReports = {0};
        CoordinationProcedure procedure = r -> {
            List<Action> out = new ArrayList<>();
            int onBall = -1;
            double best = Double.MAX_VALUE;
            for (var e : r.reports().entrySet()) {
                var c = (TeamMessage.Complete) e.getValue();
                double[] p = FORMATION[e.getKey() - 1];
                if (Math.abs(c.x() - p[0]) > 0.021 || Math.abs(c.y() - p[1]) > 0.021) wrongReports[0]++;
                double d = Math.hypot(c.x() - BALL_X, c.y() - BALL_Y);
                if (d < best) {
                    best = d;
                    onBall = e.getKey();
                }
            }
            expected.clear();
            for (int u : r.reports().keySet()) {
                double[] p = FORMATION[u - 1];
                Action a = u == onBall ? Action.of(u, ActionId.ON_BALL)
                        : Action.walkTo(u, p[0] + 0.5 * (r.round() % 8), p[1] - 0.25, 10.0 * u);
                out.add(a);
                expected.put(u, a);
            }
            return out;
        };
        CoordinatorRounds coordinator = new CoordinatorRounds(config, key, TEAM, procedure);
        FieldPlayerRounds[] players = new FieldPlayerRounds[n + 1];
        int[] index = new int[n + 1];
        long[] connectAt = new long[n + 1];
        for (int u = 1; u <= n; u++) {
            if (u != config.coordinator()) players[u] = new FieldPlayerRounds(config, u, key, TEAM);
            connectAt[u] = (long) (u - 1) * connectEvery;
            index[u] = -1;
        }
        int[] opponentIndex = new int[opponents == Opponents.NONE ? 0 : 11];
        String[] lastHeardOurs = new String[opponentIndex.length];
        for (int k = 0; k < opponentIndex.length; k++) {
            opponentIndex[k] = server.connect(new SimulatedServer.Agent(OPPONENT, -FORMATION[k][0], -FORMATION[k][1]));
        }

        List<Round> rounds = new ArrayList<>();
        long startSaid = -1;
        int round = 0;
        long roundStart = 0, complete = 0;
        int heardReports = 0, actionsHeard = 0, wrongActions = 0;
        long lastAction = 0;
        for (long cycle = 0; cycle < cycles; cycle++) {
            for (int u = 1; u <= n; u++) {
                if (index[u] < 0 && cycle >= connectAt[u] && !absent.contains(u)) {
                    index[u] = server.connect(new SimulatedServer.Agent(TEAM, FORMATION[u - 1][0], FORMATION[u - 1][1]));
                }
            }
            List<List<Hear>> hears = server.deliver();
            String[] said = new String[hears.size()];
            for (int k = 0; k < opponentIndex.length; k++) {
                int i = opponentIndex[k];
                for (Hear h : hears.get(i)) if (!h.self() && (h.team() == null || h.team().equals(TEAM))) lastHeardOurs[k] = h.message();
                if (opponents == Opponents.REPLAY && lastHeardOurs[k] != null) {
                    said[i] = lastHeardOurs[k];
                    lastHeardOurs[k] = null;
                } else {
                    said[i] = randomText(random);
                }
            }
            for (int u = 1; u <= n; u++) {
                int i = index[u];
                if (i < 0) continue;
                ChannelOutput out;
                if (u == config.coordinator()) {
                    out = coordinator.step(cycle, PlayMode.PLAY_ON, hears.get(i));
                    for (ChannelEvent e : out.events()) {
                        if (e instanceof ChannelEvent.RoundStarted s) {
                            if (round > 0) rounds.add(new Round(round, roundStart, complete, heardReports, lastAction, actionsHeard));
                            round = s.round();
                            roundStart = s.cycle();
                            if (round == 1) startSaid = s.cycle();
                            actionsHeard = 0;
                            lastAction = -1;
                            complete = -1;
                        } else if (e instanceof ChannelEvent.ReportsComplete c) {
                            complete = c.cycle();
                            heardReports = c.heard();
                        }
                    }
                } else {
                    final int unum = u;
                    out = players[u].step(cycle, PlayMode.PLAY_ON, hears.get(i),
                            () -> new TeamMessage.Complete(unum, FORMATION[unum - 1][0], FORMATION[unum - 1][1], 0, BALL_X, BALL_Y));
                    for (ChannelEvent e : out.events()) {
                        if (e instanceof ChannelEvent.ActionReceived a) {
                            actionsHeard++;
                            lastAction = Math.max(lastAction, a.cycle());
                            Action want = expected.get(u);
                            Action got = a.action();
                            if (want == null || want.id() != got.id() || Math.abs(want.x() - got.x()) > 0.021
                                    || Math.abs(want.y() - got.y()) > 0.021
                                    || TeamMessageCodecTest.angleDiff(want.thetaDeg(), got.thetaDeg()) > 0.71) {
                                wrongActions++;
                            }
                        }
                    }
                }
                said[i] = out.say();
            }
            server.said(said);
        }
        long rejected = 0;
        for (TeamMessageCodec.Rejection why : TeamMessageCodec.Rejection.values()) {
            rejected += coordinator.rejected(why);
            for (FieldPlayerRounds p : players) if (p != null) rejected += p.rejected(why);
        }
        return new Result(startSaid, rounds, wrongReports[0], wrongActions, rejected);
    }

    /** 20 characters a server delivers: printable ASCII without space and parentheses. */
    static String randomText(Random r) {
        char[] c = new char[20];
        for (int i = 0; i < c.length; i++) {
            char ch;
            do {
                ch = (char) (0x21 + r.nextInt(0x7f - 0x21));
            } while (ch == '(' || ch == ')');
            c[i] = ch;
        }
        return new String(c);
    }

    static String describe(String name, ChannelSimulation sim, int cycles) {
        Result r = sim.run(cycles);
        if (r.rounds().size() < 2) return String.format("%-44s fewer than 2 rounds in %d cycles", name, cycles);
        Round f = r.first();
        int present = sim.config.fieldPlayers() - sim.absent.size();
        String first = f.reportsHeard() < present ? "not all" : f.hearAll() + "/" + f.fullRound();
        double hear = r.steady().stream().mapToLong(Round::hearAll).average().orElse(Double.NaN);
        double full = r.steady().stream().mapToLong(Round::fullRound).average().orElse(Double.NaN);
        double reports = r.rounds().stream().mapToInt(Round::reportsHeard).average().orElse(Double.NaN);
        double actions = r.rounds().stream().mapToInt(Round::actionsHeard).average().orElse(Double.NaN);
        boolean lossy = r.steady().stream().anyMatch(x -> x.reportsHeard() < present);
        String later = lossy ? "not all" : String.format("%.1f/%.1f", hear, full);
        return String.format("%-44s %6d %13s %15s %9.1f %9.1f %6d %6d %9d",
                name, r.startSaid(), first, later, reports, actions,
                r.wrongReports(), r.wrongActions(), r.rejected());
    }

    public static void main(String[] args) {
        int cycles = 3000; // 60 s of simulated time
        System.out.println("SIMULATION of rcssserver3d's say/hear rules (not the real server), " + cycles + " cycles, 11 players");
        System.out.println("times in cycles of 20 ms; first round counted from its \"s\", later rounds from their first report slot");
        System.out.printf("%-44s %6s %13s %15s %9s %9s %6s %6s %9s%n", "scenario", "s@", "1st hear/rnd",
                "later hear/rnd", "reports", "actions", "badRep", "badAct", "rejected");
        ChannelSimulation base = new ChannelSimulation();
        System.out.println(describe("slot 2, no opponents", base, cycles));
        ChannelSimulation random = new ChannelSimulation();
        random.opponents = Opponents.RANDOM;
        System.out.println(describe("slot 2, opponents say random 20 chars", random, cycles));
        ChannelSimulation randomUnlabelled = new ChannelSimulation();
        randomUnlabelled.opponents = Opponents.RANDOM;
        randomUnlabelled.labelled = false;
        System.out.println(describe("slot 2, opponents random, no team labels", randomUnlabelled, cycles));
        ChannelSimulation replay = new ChannelSimulation();
        replay.opponents = Opponents.REPLAY;
        replay.labelled = false;
        System.out.println(describe("slot 2, opponents replay ours, no team labels", replay, cycles));
        ChannelSimulation slot1 = new ChannelSimulation();
        slot1.config = ChannelConfig.DEFAULT.withSlotCycles(1);
        System.out.println(describe("slot 1, no opponents", slot1, cycles));
        ChannelSimulation slot3 = new ChannelSimulation();
        slot3.config = ChannelConfig.DEFAULT.withSlotCycles(3);
        System.out.println(describe("slot 3 (thesis 4.7), no opponents", slot3, cycles));
        ChannelSimulation thesis = new ChannelSimulation();
        thesis.config = ChannelConfig.thesis();
        System.out.println(describe("thesis setting (slot 3, compute 6 cycles)", thesis, cycles));
        ChannelSimulation missing = new ChannelSimulation();
        missing.absent = Set.of(7);
        System.out.println(describe("slot 2, player 7 never connects", missing, cycles));
    }
}

package phalanx.comm.team;

import phalanx.comm.effector.EffectorMessage;
import phalanx.comm.perception.Hear;

import java.util.ArrayList;
import java.util.List;

/**
 * The say/hear rules of rcssserver3d, for simulations (not the real server):
 * <ul>
 * <li>a say of more than 20 characters, or with a character the server does not deliver, is dropped:
 *     nobody hears it, not even the speaker (S4: the 21-character message);</li>
 * <li>said in the reply to perception c, heard in perception c + latency (S4: 2);</li>
 * <li>the speaker hears itself ("self"), whatever else it hears;</li>
 * <li>each listener has one capacity for team-mates and one for opponents (AgentState: start 2,
 *     a message costs 2 and is dropped if less is left, +1 a cycle up to 2): so one team-mate message
 *     every 2 cycles (S4: m351 lost one cycle after m350), and opponents cannot use ours up;</li>
 * <li>of several messages in one cycle, the first speaker in connection order wins;</li>
 * <li>no message beyond 50 m;</li>
 * <li>the direction is the field-frame bearing from the listener to the speaker.</li>
 * </ul>
 */
final class SimulatedServer {
    static final double AUDIO_CUT_DISTANCE = 50;

    record Agent(String team, double x, double y) {
    }

    private record Said(int speaker, String text) {
    }

    private final List<Agent> agents = new ArrayList<>();
    private final int latency;
    private final boolean labelled;
    private int[] mateCap = new int[0], oppCap = new int[0];
    private final List<List<Said>> pipeline = new ArrayList<>();

    /** {@code labelled}: the server names the speaker's team in each hear (0.7: yes; older: no). */
    SimulatedServer(int latency, boolean labelled) {
        this.latency = latency;
        this.labelled = labelled;
        for (int i = 0; i < latency; i++) pipeline.add(new ArrayList<>());
    }

    /** Adds an agent in connection order; returns its index. */
    int connect(Agent a) {
        agents.add(a);
        mateCap = java.util.Arrays.copyOf(mateCap, agents.size());
        oppCap = java.util.Arrays.copyOf(oppCap, agents.size());
        mateCap[agents.size() - 1] = 2;
        oppCap[agents.size() - 1] = 2;
        return agents.size() - 1;
    }

    /**
     * The hears of this cycle's perceptions, one list per agent, from the messages said {@code latency}
     * cycles ago; then records what the agents say in reply ({@code said[i]}, null for nothing).
     */
    List<List<Hear>> deliver() {
        List<Said> arriving = pipeline.remove(0);
        int n = agents.size();
        String[] mate = new String[n], opp = new String[n], self = new String[n];
        int[] mateFrom = new int[n], oppFrom = new int[n];
        for (Said s : arriving) {
            if (EffectorMessage.sayProblem(s.text) != null) continue;
            Agent speaker = agents.get(s.speaker);
            for (int l = 0; l < n; l++) {
                if (l == s.speaker) {
                    self[l] = s.text;
                    continue;
                }
                Agent listener = agents.get(l);
                if (Math.hypot(listener.x - speaker.x, listener.y - speaker.y) > AUDIO_CUT_DISTANCE) continue;
                if (listener.team.equals(speaker.team)) {
                    if (mateCap[l] < 2) continue;
                    mateCap[l] -= 2;
                    mate[l] = s.text;
                    mateFrom[l] = s.speaker;
                } else {
                    if (oppCap[l] < 2) continue;
                    oppCap[l] -= 2;
                    opp[l] = s.text;
                    oppFrom[l] = s.speaker;
                }
            }
        }
        List<List<Hear>> out = new ArrayList<>(n);
        for (int l = 0; l < n; l++) {
            mateCap[l] = Math.min(2, mateCap[l] + 1);
            oppCap[l] = Math.min(2, oppCap[l] + 1);
            List<Hear> hears = new ArrayList<>(3);
            String team = agents.get(l).team;
            if (self[l] != null) hears.add(new Hear(labelled ? team : null, 0, true, 0, self[l]));
            if (mate[l] != null) hears.add(hear(l, mateFrom[l], mate[l]));
            if (opp[l] != null) hears.add(hear(l, oppFrom[l], opp[l]));
            out.add(hears);
        }
        return out;
    }

    private Hear hear(int listener, int speaker, String text) {
        Agent a = agents.get(listener), b = agents.get(speaker);
        double dir = Math.toDegrees(Math.atan2(b.y - a.y, b.x - a.x));
        return new Hear(labelled ? b.team : null, 0, false, dir, text);
    }

    /** What the agents said in reply to this cycle's perceptions, by agent index (null: nothing). */
    void said(String[] texts) {
        List<Said> now = new ArrayList<>();
        for (int i = 0; i < texts.length; i++) if (texts[i] != null) now.add(new Said(i, texts[i]));
        pipeline.add(now);
    }
}

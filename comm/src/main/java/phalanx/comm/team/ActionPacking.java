package phalanx.comm.team;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.function.ToIntFunction;

/** The first-fit packing of one dispatch into "a" messages that both team codecs share; only the sizes differ. */
final class ActionPacking {
    private ActionPacking() {}

    /**
     * Packs the actions into as few messages of {@code budgetBits} of entries as fit (first fit, largest entries
     * first), each telling how many follow. Refuses two actions for one recipient and more than {@code maxMessages}
     * messages ({@code unit} names them in the error: "messages", "frames").
     */
    static List<TeamMessage.Actions> pack(Collection<Action> actions, ToIntFunction<ActionId> entryBits, int budgetBits,
                                          int maxMessages, String unit) {
        List<Action> sorted = new ArrayList<>(actions);
        boolean[] seen = new boolean[16];
        for (Action a : sorted) {
            if (a.recipient() < 1 || a.recipient() > 15) throw new IllegalArgumentException("recipient must be 1-15, got " + a.recipient());
            if (seen[a.recipient()]) throw new IllegalArgumentException("two actions for player " + a.recipient());
            seen[a.recipient()] = true;
        }
        sorted.sort(Comparator.comparingInt((Action a) -> -entryBits.applyAsInt(a.id())).thenComparingInt(Action::recipient));
        List<List<Action>> bins = new ArrayList<>();
        List<Integer> free = new ArrayList<>();
        for (Action a : sorted) {
            int need = entryBits.applyAsInt(a.id());
            int bin = 0;
            while (bin < bins.size() && free.get(bin) < need) bin++;
            if (bin == bins.size()) {
                bins.add(new ArrayList<>());
                free.add(budgetBits);
            }
            bins.get(bin).add(a);
            free.set(bin, free.get(bin) - need);
        }
        if (bins.size() > maxMessages) {
            throw new IllegalArgumentException(actions.size() + " actions need " + bins.size() + " " + unit + ", at most "
                    + maxMessages + " fit in one dispatch");
        }
        List<TeamMessage.Actions> messages = new ArrayList<>(bins.size());
        for (int i = 0; i < bins.size(); i++) messages.add(new TeamMessage.Actions(bins.size() - 1 - i, bins.get(i)));
        return messages;
    }
}

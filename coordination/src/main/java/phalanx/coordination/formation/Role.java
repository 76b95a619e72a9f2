package phalanx.coordination.formation;

import java.util.List;

/** The roles of the team formation (thesis 5.9, Tables 5.1 and 5.2). */
public enum Role {
    GK("Goalkeeper"),
    DL("Defender Left"), DC("Defender Center"), DR("Defender Right"),
    ML("Midfielder Left"), MC("Midfielder Center"), MR("Midfielder Right"),
    FS("Forward Support"),
    FL("Forward Left"), FC("Forward Center"), FR("Forward Right");

    private final String title;

    Role(String title) { this.title = title; }

    public String title() { return title; }

    private static final List<Role> NINE = List.of(GK, DL, DC, DR, ML, MR, FL, FC, FR);
    /** rcssservermj's ssim rule book (docs/rcssservermj.md): three defenders, two midfielders, one forward. */
    private static final List<Role> SEVEN = List.of(GK, DL, DC, DR, ML, MR, FC);
    private static final List<Role> ELEVEN = List.of(GK, DL, DC, DR, ML, MC, MR, FS, FL, FC, FR);

    /** The roles of a team of 7 (rcssservermj), 9 (0.6.5) or 11 (0.6.6 and later). */
    public static List<Role> forPlayers(int players) {
        if (players == 7) return SEVEN;
        if (players == 9) return NINE;
        if (players == 11) return ELEVEN;
        throw new IllegalArgumentException("formations exist for 7, 9 and 11 players, not " + players);
    }
}

package phalanx.motion;

import phalanx.motion.phase.Check;
import phalanx.motion.phase.Phase;
import phalanx.motion.phase.PhaseMotion;
import phalanx.motion.phase.PhaseMotionLoader;
import phalanx.motion.webots.TextMotionLoader;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The motions a player can request, by name: every {@code *.xml} (phase motion, 4.5.1) and
 * {@code *.motion} (Webots text motion, 4.5.3) in a folder, named after the file. Loaded once at
 * start; any bad file stops the start with a message naming file, line and field. A player loads
 * the folder for its robot type ({@link #load(Path, int)}: files in {@code typeN/} replace theirs).
 */
public final class MotionLibrary {
    private final Map<String, Motion> motions;

    private MotionLibrary(Map<String, Motion> motions) { this.motions = Map.copyOf(motions); }

    public static MotionLibrary of(Motion... motions) {
        Map<String, Motion> m = new LinkedHashMap<>();
        for (Motion x : motions) {
            if (m.put(x.name(), x) != null) throw new IllegalArgumentException("two motions named '" + x.name() + "'");
        }
        return new MotionLibrary(m);
    }

    public static MotionLibrary load(Path dir) throws MotionFileException {
        return load(dir, null);
    }

    /**
     * The folder's motions for one robot type: each file in {@code dir/type<N>/} replaces the folder's
     * motion of the same name (a motion tuned for that body, motions/README.md). A file there that
     * replaces nothing is an error, since a misspelt name would otherwise never be played.
     */
    public static MotionLibrary load(Path dir, int robotType) throws MotionFileException {
        return load(dir, dir.resolve("type" + robotType));
    }

    private static MotionLibrary load(Path dir, Path own) throws MotionFileException {
        if (!Files.isDirectory(dir)) throw new MotionFileException(dir, 0, null, null, "not a folder of motion files");
        Map<String, Motion> m = read(dir);
        if (own != null && Files.isDirectory(own)) {
            for (Motion x : read(own).values()) {
                if (m.replace(x.name(), x) == null) {
                    throw new MotionFileException(x.source(), 0, null, null,
                            "replaces no motion of " + dir + " (have " + m.keySet() + ")", null);
                }
            }
        }
        checkSwitches(m);
        return new MotionLibrary(m);
    }

    private static Map<String, Motion> read(Path dir) throws MotionFileException {
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(Files::isRegularFile).sorted().toList();
        } catch (IOException e) {
            throw new MotionFileException(dir.toString(), 0, null, null, "cannot list: " + e.getMessage(), e);
        }
        Map<String, Motion> m = new LinkedHashMap<>();
        for (Path f : files) {
            String n = f.getFileName().toString();
            Motion motion;
            if (n.endsWith(".xml")) motion = PhaseMotionLoader.load(f);
            else if (n.endsWith(".motion")) motion = TextMotionLoader.load(f);
            else continue;
            Motion before = m.put(motion.name(), motion);
            if (before != null) throw new MotionFileException(f, 0, null, null, "a second motion named '" + motion.name() + "' (also " + before.source() + ")");
        }
        return m;
    }

    /** A check's switch must name another loaded motion (a typo would otherwise surface mid-game). */
    private static void checkSwitches(Map<String, Motion> m) throws MotionFileException {
        for (Motion motion : m.values()) {
            if (!(motion instanceof PhaseMotion pm)) continue;
            for (Phase p : pm.phases()) {
                Check c = p.check();
                if (c == null || c.switchTo() == null) continue;
                if (c.switchTo().equals(motion.name()) || !m.containsKey(c.switchTo())) {
                    throw new MotionFileException(motion.source(), c.line(), "phase '" + p.name() + "'", "check/switch",
                            "'" + c.switchTo() + "' is not another motion of this folder (have " + m.keySet() + ")", null);
                }
            }
        }
    }

    /** The motion with this name, or null. */
    public Motion get(String name) { return name == null ? null : motions.get(name); }

    public Set<String> names() { return motions.keySet(); }

    public Collection<Motion> all() { return motions.values(); }
}

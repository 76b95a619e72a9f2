package phalanx.motion.phase;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import phalanx.comm.perception.Joint;
import phalanx.motion.MotionFileException;
import phalanx.model.robot.JointLimits;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Loads an XML phase motion (4.5.1) with jackson-dataformat-xml and validates it completely, so a
 * bad file fails at start with the file, line, phase and field, never in the middle of a game.
 * Format (see motions/README.md):
 * <pre>
 * &lt;motion first="Start"&gt;                        first: optional, default the first phase
 *   &lt;phase name="Start" next="Step1" swing="left"&gt; next, swing: optional
 *     &lt;effectors&gt;&lt;llj3&gt;20&lt;/llj3&gt;...&lt;/effectors&gt;  targets in degrees (hj1.. or he1.. names)
 *     &lt;duration&gt;120&lt;/duration&gt;                   milliseconds, &gt; 0
 *     &lt;finalize&gt;Final&lt;/finalize&gt;                 optional
 *     &lt;check axis="forward" min="-1" max="0.5" else="Phase" | switch="motion"/&gt;   optional
 *   &lt;/phase&gt; ...
 * &lt;/motion&gt;
 * </pre>
 */
public final class PhaseMotionLoader {
    private static final XmlFactory XML = new XmlFactory();
    private static final Set<String> ROOT_FIELDS = Set.of("first", "description", "phase");
    private static final Set<String> PHASE_FIELDS = Set.of("name", "next", "finalize", "swing", "effectors", "duration", "check");
    private static final Set<String> CHECK_FIELDS = Set.of("axis", "min", "max", "else", "switch");

    private PhaseMotionLoader() {}

    /** Loads a file; the motion's name is the file name without its extension. */
    public static PhaseMotion load(Path file) throws MotionFileException {
        String fileName = file.getFileName().toString();
        int dot = fileName.lastIndexOf('.');
        String name = dot > 0 ? fileName.substring(0, dot) : fileName;
        try (InputStream in = Files.newInputStream(file)) {
            return parse(name, file.toString(), in);
        } catch (IOException e) {
            throw new MotionFileException(file.toString(), 0, null, null, "cannot read: " + e.getMessage(), e);
        }
    }

    /** Parses a motion from a stream; {@code source} names it in messages. */
    public static PhaseMotion parse(String name, String source, InputStream in) throws MotionFileException {
        XmlNode root = readTree(source, in);
        return build(name, source, root);
    }

    private static XmlNode readTree(String source, InputStream in) throws MotionFileException {
        try (JsonParser p = XML.createParser(in)) {
            JsonToken t = p.nextToken();
            if (t == null) throw new MotionFileException(source, 0, null, null, "empty file: no <motion> element", null);
            int line = p.currentLocation().getLineNr();
            if (t != JsonToken.START_OBJECT) {
                throw new MotionFileException(source, line, null, "phase", "no first phase: the file has no <phase> element", null);
            }
            return readObject(p, "motion", line, source);
        } catch (JsonProcessingException e) {
            int line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
            throw new MotionFileException(source, Math.max(line, 0), null, null, "not well-formed XML: " + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw new MotionFileException(source, 0, null, null, "cannot read: " + e.getMessage(), e);
        }
    }

    private static XmlNode readObject(JsonParser p, String name, int line, String source) throws IOException, MotionFileException {
        XmlNode node = new XmlNode(name, null, line);
        JsonToken t;
        while ((t = p.nextToken()) != JsonToken.END_OBJECT) {
            if (t == null) throw new MotionFileException(source, line, null, name, "file ends inside <" + name + ">", null);
            String field = p.currentName();
            int fieldLine = p.currentLocation().getLineNr();
            JsonToken v = p.nextToken();
            if (v == JsonToken.START_OBJECT) {
                node.children.add(readObject(p, field, fieldLine, source));
            } else if (v == JsonToken.START_ARRAY) {
                throw new MotionFileException(source, fieldLine, null, field, "unexpected list", null);
            } else {
                String text = v == JsonToken.VALUE_NULL ? "" : p.getValueAsString("");
                node.children.add(new XmlNode(field, text.strip(), fieldLine));
            }
        }
        return node;
    }

    private static PhaseMotion build(String name, String source, XmlNode root) throws MotionFileException {
        String first = null;
        int firstLine = root.line;
        List<XmlNode> phaseNodes = new ArrayList<>();
        for (XmlNode c : root.children) {
            if (c.name.isEmpty()) throw new MotionFileException(source, c.line, null, null, "unexpected text '" + c.text + "' in <motion> (it holds <phase> elements)", null);
            if (!ROOT_FIELDS.contains(c.name)) {
                throw new MotionFileException(source, c.line, null, c.name, "unknown field (expected " + sorted(ROOT_FIELDS) + ")", null);
            }
            switch (c.name) {
                case "first" -> { first = leafText(source, c, null); firstLine = c.line; }
                case "phase" -> phaseNodes.add(c);
                default -> { } // description: free text for people
            }
        }
        if (phaseNodes.isEmpty()) throw new MotionFileException(source, root.line, null, "phase", "no first phase: the file has no <phase> element", null);

        // First pass: names, so links can be resolved and named in messages.
        Map<String, Integer> index = new HashMap<>();
        List<String> names = new ArrayList<>();
        for (XmlNode pn : phaseNodes) {
            if (pn.isLeaf()) throw new MotionFileException(source, pn.line, "phase #" + (names.size() + 1), null, "a phase needs a name, effectors and a duration", null);
            XmlNode n = single(source, pn, "name", "phase #" + (names.size() + 1));
            if (n == null) throw new MotionFileException(source, pn.line, "phase #" + (names.size() + 1), "name", "missing", null);
            String phaseName = leafText(source, n, "phase #" + (names.size() + 1));
            if (phaseName.isEmpty()) throw new MotionFileException(source, n.line, "phase #" + (names.size() + 1), "name", "empty", null);
            if (index.putIfAbsent(phaseName, names.size()) != null) {
                throw new MotionFileException(source, n.line, "phase '" + phaseName + "'", "name", "a second phase with this name", null);
            }
            names.add(phaseName);
        }

        List<Phase> phases = new ArrayList<>();
        for (int i = 0; i < phaseNodes.size(); i++) phases.add(buildPhase(source, phaseNodes.get(i), names.get(i), index));

        int firstIndex = 0;
        if (first != null) {
            Integer fi = index.get(first);
            if (fi == null) throw new MotionFileException(source, firstLine, null, "first", "no first phase: no phase is named '" + first + "' (phases: " + names + ")", null);
            firstIndex = fi;
        }
        checkEnds(source, phases, phaseNodes);
        return new PhaseMotion(name, source, phases, firstIndex);
    }

    private static Phase buildPhase(String source, XmlNode pn, String phaseName, Map<String, Integer> index) throws MotionFileException {
        String part = "phase '" + phaseName + "'";
        for (XmlNode c : pn.children) {
            if (c.name.isEmpty()) throw new MotionFileException(source, c.line, part, null, "unexpected text '" + c.text + "' in <phase>", null);
            if (!PHASE_FIELDS.contains(c.name)) throw new MotionFileException(source, c.line, part, c.name, "unknown field (expected " + sorted(PHASE_FIELDS) + ")", null);
        }
        int next = link(source, pn, "next", part, index);
        int fin = link(source, pn, "finalize", part, index);

        Phase.Swing swing = Phase.Swing.NONE;
        XmlNode sw = single(source, pn, "swing", part);
        if (sw != null) {
            String s = leafText(source, sw, part).toLowerCase(Locale.ROOT);
            swing = switch (s) {
                case "left" -> Phase.Swing.LEFT;
                case "right" -> Phase.Swing.RIGHT;
                case "none", "" -> Phase.Swing.NONE;
                default -> throw new MotionFileException(source, sw.line, part, "swing", "'" + s + "' is not left, right or none", null);
            };
        }

        XmlNode d = single(source, pn, "duration", part);
        if (d == null) throw new MotionFileException(source, pn.line, part, "duration", "missing (milliseconds, > 0)", null);
        String ds = leafText(source, d, part);
        int duration;
        try {
            duration = Integer.parseInt(ds);
        } catch (NumberFormatException e) {
            throw new MotionFileException(source, d.line, part, "duration", "'" + ds + "' is not a whole number of milliseconds", null);
        }
        if (duration <= 0) throw new MotionFileException(source, d.line, part, "duration", duration + " ms: a duration must be > 0", null);

        double[] targets = new double[Joint.COUNT];
        Arrays.fill(targets, Double.NaN);
        XmlNode eff = single(source, pn, "effectors", part);
        if (eff == null) throw new MotionFileException(source, pn.line, part, "effectors", "missing (use <effectors/> for a phase that holds still)", null);
        if (eff.isLeaf() && !eff.text.isEmpty()) throw new MotionFileException(source, eff.line, part, "effectors", "expected joint elements such as <llj3>20</llj3>, found text '" + eff.text + "'", null);
        for (XmlNode j : eff.children) {
            String field = "effectors/" + j.name;
            Joint joint = Joint.byName(j.name);
            if (joint == null) throw new MotionFileException(source, j.line, part, field, "unknown joint '" + j.name + "' (use hj1, hj2, laj1-4, raj1-4, llj1-7, rlj1-7 or their effector names)", null);
            if (!j.isLeaf()) throw new MotionFileException(source, j.line, part, field, "expected a number of degrees, found nested elements", null);
            double v;
            try {
                v = Double.parseDouble(j.text);
            } catch (NumberFormatException e) {
                throw new MotionFileException(source, j.line, part, field, "'" + j.text + "' is not a number of degrees", null);
            }
            if (!Double.isFinite(v)) throw new MotionFileException(source, j.line, part, field, "'" + j.text + "' is not finite", null);
            if (!JointLimits.contains(joint, v)) {
                throw new MotionFileException(source, j.line, part, field, v + " deg is outside the joint's range [" + JointLimits.minDeg(joint) + ", " + JointLimits.maxDeg(joint) + "]", null);
            }
            if (!Double.isNaN(targets[joint.ordinal()])) throw new MotionFileException(source, j.line, part, field, "joint " + joint.perceptorName() + " listed twice", null);
            targets[joint.ordinal()] = v;
        }
        return new Phase(phaseName, targets, duration, next, fin, swing, check(source, pn, part, index));
    }

    /** The optional torso check (see {@link Check}): axis, a range within [-1, 1], and else (a phase) or switch (a motion). */
    private static Check check(String source, XmlNode pn, String part, Map<String, Integer> index) throws MotionFileException {
        XmlNode c = single(source, pn, "check", part);
        if (c == null) return null;
        if (c.isLeaf()) throw new MotionFileException(source, c.line, part, "check", "needs axis, min and/or max, and else or switch", null);
        for (XmlNode f : c.children) {
            if (!CHECK_FIELDS.contains(f.name)) throw new MotionFileException(source, f.line, part, "check/" + f.name, "unknown field (expected " + sorted(CHECK_FIELDS) + ")", null);
        }
        XmlNode a = single(source, c, "axis", part);
        if (a == null) throw new MotionFileException(source, c.line, part, "check/axis", "missing (right, forward or up)", null);
        String as = leafText(source, a, part).toLowerCase(Locale.ROOT);
        Check.Axis axis = switch (as) {
            case "right" -> Check.Axis.RIGHT;
            case "forward" -> Check.Axis.FORWARD;
            case "up" -> Check.Axis.UP;
            default -> throw new MotionFileException(source, a.line, part, "check/axis", "'" + as + "' is not right, forward or up", null);
        };
        XmlNode mn = single(source, c, "min", part), mx = single(source, c, "max", part);
        if (mn == null && mx == null) throw new MotionFileException(source, c.line, part, "check", "give min or max (a share of up in [-1, 1]); without them the check always passes", null);
        double min = share(source, mn, part, "check/min", -1), max = share(source, mx, part, "check/max", 1);
        if (min > max) throw new MotionFileException(source, c.line, part, "check", "min " + min + " is above max " + max, null);
        int elsePhase = link(source, c, "else", part, index);
        XmlNode sw = single(source, c, "switch", part);
        String switchTo = sw == null ? null : leafText(source, sw, part);
        if (switchTo != null && switchTo.isEmpty()) throw new MotionFileException(source, sw.line, part, "check/switch", "empty (name a motion)", null);
        if ((elsePhase >= 0) == (switchTo != null)) throw new MotionFileException(source, c.line, part, "check", "give exactly one of else (a phase of this file) and switch (another motion)", null);
        return new Check(axis, min, max, elsePhase, switchTo, c.line);
    }

    private static double share(String source, XmlNode n, String part, String field, double absent) throws MotionFileException {
        if (n == null) return absent;
        String t = leafText(source, n, part);
        double v;
        try {
            v = Double.parseDouble(t);
        } catch (NumberFormatException e) {
            throw new MotionFileException(source, n.line, part, field, "'" + t + "' is not a number", null);
        }
        if (!(v >= -1 && v <= 1)) throw new MotionFileException(source, n.line, part, field, t + " is outside [-1, 1] (a share of up along the axis)", null);
        return v;
    }

    private static int link(String source, XmlNode pn, String field, String part, Map<String, Integer> index) throws MotionFileException {
        XmlNode n = single(source, pn, field, part);
        if (n == null) return -1;
        String target = leafText(source, n, part);
        if (target.isEmpty()) return -1;
        Integer i = index.get(target);
        if (i == null) throw new MotionFileException(source, n.line, part, field, "no phase is named '" + target + "' (phases: " + index.keySet().stream().sorted().toList() + ")", null);
        return i;
    }

    /** Finalizing follows finalize links, else next links: from every phase that must reach an end. */
    private static void checkEnds(String source, List<Phase> phases, List<XmlNode> nodes) throws MotionFileException {
        for (int start = 0; start < phases.size(); start++) {
            Set<Integer> seen = new HashSet<>();
            List<String> path = new ArrayList<>();
            int i = start;
            while (i >= 0) {
                path.add(phases.get(i).name());
                if (!seen.add(i)) {
                    throw new MotionFileException(source, nodes.get(start).line, "phase '" + phases.get(start).name() + "'", "finalize",
                            "the motion can never be stopped from here: finalizing follows " + String.join(" -> ", path)
                                    + " forever; give one of these phases a <finalize> that leads to an end", null);
                }
                Phase p = phases.get(i);
                i = p.finalizeTo() >= 0 ? p.finalizeTo() : p.next();
            }
        }
    }

    private static XmlNode single(String source, XmlNode parent, String field, String part) throws MotionFileException {
        XmlNode found = null;
        for (XmlNode c : parent.children) {
            if (c.name.equals(field)) {
                if (found != null) throw new MotionFileException(source, c.line, part, field, "given twice", null);
                found = c;
            }
        }
        return found;
    }

    private static String leafText(String source, XmlNode n, String part) throws MotionFileException {
        if (!n.isLeaf()) throw new MotionFileException(source, n.line, part, n.name, "expected text, found nested elements", null);
        return n.text;
    }

    private static List<String> sorted(Set<String> s) { return s.stream().sorted().toList(); }

}

package phalanx.comm.monitor;

import java.util.ArrayList;
import java.util.List;

/**
 * The monitor port's scene graph (rcssserver3d 0.7.3, recordings README "How the ground truth was
 * obtained"): a full graph {@code (RSG 0 1)} replaces the tree, a partial one {@code (RDS 0 1)}
 * walks it in the same order and updates the transforms it carries. A player's torso is the TRF
 * two levels above the StaticMesh loading {@code models/naobody*.obj}, named by its materials
 * {@code matNum<unum>} and {@code matLeft}/{@code matRight}; the ball is the TRF above
 * {@code models/soccerball.obj}. World poses multiply the nested column-major SLT matrices.
 * Used by the motion bench only, not by players (competition servers give players no ground truth).
 */
public final class MonitorScene {
    /** A torso pose: position (m) and R (row-major) mapping torso-local (x right, y forward, z up) to field. */
    public record Pose(double x, double y, double z, double[] r) {
        /** Facing direction in the beam convention (0 = +x, counter-clockwise positive), degrees. */
        public double yawDeg() { return Math.toDegrees(Math.atan2(r[3 * 1 + 1], r[1])); }
        /** The torso's up axis' vertical component: 1 upright, 0 lying. */
        public double upZ() { return r[8]; }
        /** Lying on its front (forward axis pointing down) or back (forward axis pointing up)? */
        public double forwardZ() { return r[7]; }
        /** The torso's right axis' vertical component: positive when the right side is up. */
        public double rightZ() { return r[6]; }
    }

    private Node root;
    private double time = Double.NaN;
    private int playMode = -1;
    private int messages;

    /** Applies one monitor message. Throws IllegalArgumentException on text it cannot read. */
    public void apply(String message) {
        List<Object> top = Sexp.parseAll(message);
        messages++;
        boolean full = false, partial = false;
        for (int i = 0; i < top.size(); i++) {
            Object o = top.get(i);
            if (!(o instanceof List<?> l) || l.isEmpty()) continue;
            if (l.get(0) instanceof String head) {
                if (head.equals("RSG")) full = true;
                else if (head.equals("RDS")) partial = true;
                continue;
            }
            if (l.get(0) instanceof List<?> first && !first.isEmpty() && "nd".equals(first.get(0))) {
                if (full) root = build(l);
                else if (partial && root != null) update(root, l);
                full = partial = false;
            } else {
                header(l);
            }
        }
    }

    /** Game time from the last header that had one, NaN before. */
    public double time() { return time; }
    public int playMode() { return playMode; }
    public int messages() { return messages; }
    public boolean hasScene() { return root != null; }

    /** The torso of player {@code unum} of the team on {@code side} ("Left"/"Right"), or null. */
    public Pose torso(int unum, String side) {
        if (root == null) return null;
        return findTorso(root, identity(), unum, "mat" + side);
    }

    /**
     * The centres of every body part of player {@code unum} (torso, head, arm and leg segments and
     * the joint markers: each transform node beside the torso's in the player's group), {x, y, z}
     * each; null when the player is not in the scene. Used for the keeper's lateral reach.
     */
    public List<double[]> parts(int unum, String side) {
        if (root == null) return null;
        return findParts(root, identity(), unum, "mat" + side);
    }

    /** The ball's centre, {x, y, z}, or null. */
    public double[] ball() {
        if (root == null) return null;
        return findBall(root, identity());
    }

    // --- tree -------------------------------------------------------------------------------

    private static final class Node {
        double[] slt;                 // column-major 4x4, null = identity
        String load;                  // model loaded by a StaticMesh, or null
        final List<String> materials = new ArrayList<>();
        final List<Node> children = new ArrayList<>();
    }

    /** A list of (nd ...) children. */
    private static Node build(List<?> children) {
        Node n = new Node();
        for (Object c : children) if (c instanceof List<?> l && !l.isEmpty() && "nd".equals(l.get(0))) n.children.add(node(l));
        return n;
    }

    private static Node node(List<?> nd) {
        Node n = new Node();
        for (int i = 1; i < nd.size(); i++) {
            Object o = nd.get(i);
            if (!(o instanceof List<?> l) || l.isEmpty() || !(l.get(0) instanceof String key)) continue;
            switch (key) {
                case "nd" -> n.children.add(node(l));
                case "SLT" -> n.slt = matrix(l);
                case "load" -> n.load = l.size() > 1 ? String.valueOf(l.get(1)) : null;
                case "resetMaterials", "sMat" -> { for (int k = 1; k < l.size(); k++) n.materials.add(String.valueOf(l.get(k))); }
                default -> { }
            }
        }
        return n;
    }

    private static void update(Node full, List<?> partialChildren) {
        int k = 0;
        for (Object c : partialChildren) {
            if (!(c instanceof List<?> l) || l.isEmpty() || !"nd".equals(l.get(0))) continue;
            if (k >= full.children.size()) return; // the scene changed shape; the next RSG will fix it
            updateNode(full.children.get(k++), l);
        }
    }

    private static void updateNode(Node n, List<?> nd) {
        int k = 0;
        for (int i = 1; i < nd.size(); i++) {
            if (!(nd.get(i) instanceof List<?> l) || l.isEmpty()) continue;
            if ("SLT".equals(l.get(0))) n.slt = matrix(l);
            else if ("nd".equals(l.get(0))) {
                if (k >= n.children.size()) return;
                updateNode(n.children.get(k++), l);
            }
        }
    }

    private void header(List<?> l) {
        for (Object o : l) {
            if (o instanceof List<?> kv && kv.size() == 2 && kv.get(0) instanceof String key && kv.get(1) instanceof String v) {
                try {
                    if (key.equals("time")) time = Double.parseDouble(v);
                    else if (key.equals("play_mode")) playMode = Integer.parseInt(v);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("monitor header " + key + " is not a number: '" + v + "'");
                }
            }
        }
    }

    private static double[] matrix(List<?> l) {
        if (l.size() != 17) throw new IllegalArgumentException("SLT needs 16 numbers, got " + (l.size() - 1));
        double[] m = new double[16];
        for (int i = 0; i < 16; i++) {
            try {
                m[i] = Double.parseDouble(String.valueOf(l.get(i + 1)));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("SLT element " + i + " is not a number: '" + l.get(i + 1) + "'");
            }
        }
        return m;
    }

    // --- queries ----------------------------------------------------------------------------

    private static double[] identity() { return new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

    private static double[] times(double[] a, double[] b) { // column-major a * b
        if (b == null) return a;
        double[] c = new double[16];
        for (int col = 0; col < 4; col++)
            for (int row = 0; row < 4; row++) {
                double s = 0;
                for (int k = 0; k < 4; k++) s += a[k * 4 + row] * b[col * 4 + k];
                c[col * 4 + row] = s;
            }
        return c;
    }

    /** n is a torso if a child TRF holds the naobody mesh with the player's materials. */
    private static boolean isTorso(Node n, int unum, String sideMaterial) {
        for (Node c : n.children) {
            for (Node mesh : c.children) {
                if (mesh.load != null && mesh.load.startsWith("models/naobody")
                        && mesh.materials.contains("matNum" + unum) && mesh.materials.contains(sideMaterial)) return true;
            }
        }
        return false;
    }

    private static List<double[]> findParts(Node n, double[] world, int unum, String sideMaterial) {
        double[] w = times(world, n.slt);
        for (Node c : n.children) {
            if (!isTorso(c, unum, sideMaterial)) continue;
            List<double[]> out = new ArrayList<>();
            for (Node part : n.children) {
                double[] p = times(w, part.slt);
                out.add(new double[] {p[12], p[13], p[14]});
            }
            return out;
        }
        for (Node c : n.children) {
            List<double[]> p = findParts(c, w, unum, sideMaterial);
            if (p != null) return p;
        }
        return null;
    }

    private static Pose findTorso(Node n, double[] world, int unum, String sideMaterial) {
        double[] w = times(world, n.slt);
        if (isTorso(n, unum, sideMaterial)) {
            double[] r = {w[0], w[4], w[8], w[1], w[5], w[9], w[2], w[6], w[10]};
            return new Pose(w[12], w[13], w[14], r);
        }
        for (Node c : n.children) {
            Pose p = findTorso(c, w, unum, sideMaterial);
            if (p != null) return p;
        }
        return null;
    }

    private static double[] findBall(Node n, double[] world) {
        double[] w = times(world, n.slt);
        for (Node c : n.children) if (c.load != null && c.load.equals("models/soccerball.obj")) return new double[] {w[12], w[13], w[14]};
        for (Node c : n.children) {
            double[] b = findBall(c, w);
            if (b != null) return b;
        }
        return null;
    }

    /** A minimal S-expression reader for the monitor's text (atoms as strings, lists as lists). */
    static final class Sexp {
        private Sexp() {}

        static List<Object> parseAll(String s) {
            List<Object> out = new ArrayList<>();
            int[] pos = {0};
            while (true) {
                skip(s, pos);
                if (pos[0] >= s.length()) return out;
                if (s.charAt(pos[0]) != '(') throw new IllegalArgumentException("monitor message: expected '(' at " + pos[0]);
                out.add(list(s, pos));
            }
        }

        private static List<Object> list(String s, int[] pos) {
            pos[0]++; // '('
            List<Object> l = new ArrayList<>();
            while (true) {
                skip(s, pos);
                if (pos[0] >= s.length()) throw new IllegalArgumentException("monitor message: unbalanced parentheses (truncated?)");
                char c = s.charAt(pos[0]);
                if (c == ')') { pos[0]++; return l; }
                if (c == '(') { l.add(list(s, pos)); continue; }
                int start = pos[0];
                while (pos[0] < s.length() && " \t\r\n()".indexOf(s.charAt(pos[0])) < 0) pos[0]++;
                l.add(s.substring(start, pos[0]));
            }
        }

        private static void skip(String s, int[] pos) {
            while (pos[0] < s.length() && Character.isWhitespace(s.charAt(pos[0]))) pos[0]++;
        }
    }
}

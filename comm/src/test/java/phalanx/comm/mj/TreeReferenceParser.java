package phalanx.comm.mj;

import phalanx.comm.sexp.MalformedMessageException;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The tree parser {@link MjPerceptionParser} had until issue 20, kept as the reference its single-pass
 * replacement is checked against (MjPerceptionParserReferenceTest) and timed against (MjParserBenchmark).
 * Parses the rcssservermj (rcsssmj 0.2.1) perception dialect into {@link MjPerception}: builds a List tree
 * of substrings, then walks it. Unknown nodes are ignored; every defect ends in
 * {@link MalformedMessageException}.
 */
final class TreeReferenceParser {
    private String s;
    private int p;

    MjPerception parse(String message) throws MalformedMessageException {
        s = message;
        p = 0;
        List<Object> top = new ArrayList<>();
        ws();
        while (p < s.length()) {
            if (s.charAt(p) != '(') throw new MalformedMessageException("expected '('", p);
            top.add(list(0));
            ws();
        }
        try {
            return build(top);
        } catch (RuntimeException e) {
            throw new MalformedMessageException("bad node: " + e.getMessage(), p);
        }
    }

    private void ws() { while (p < s.length() && Character.isWhitespace(s.charAt(p))) p++; }

    private List<Object> list(int depth) throws MalformedMessageException {
        if (depth > 32) throw new MalformedMessageException("nesting too deep", p);
        p++; // '('
        List<Object> out = new ArrayList<>();
        while (true) {
            ws();
            if (p >= s.length()) throw new MalformedMessageException("unexpected end, ')' missing", p);
            char c = s.charAt(p);
            if (c == ')') { p++; return out; }
            if (c == '(') { out.add(list(depth + 1)); continue; }
            int st = p;
            while (p < s.length() && s.charAt(p) != '(' && s.charAt(p) != ')' && !Character.isWhitespace(s.charAt(p))) p++;
            out.add(s.substring(st, p));
        }
    }

    private static String head(Object o) {
        if (o instanceof List<?> l && !l.isEmpty() && l.get(0) instanceof String h) return h;
        return "";
    }

    private static List<?> child(List<?> l, String name) {
        for (Object o : l) if (head(o).equals(name)) return (List<?>) o;
        throw new IllegalArgumentException("missing (" + name + ")");
    }

    private static double num(Object o) {
        if (!(o instanceof String t)) throw new IllegalArgumentException("expected a number");
        double d = Double.parseDouble(t);
        if (!Double.isFinite(d)) throw new IllegalArgumentException("non-finite number " + t);
        return d;
    }

    private static String atom(Object o) {
        if (!(o instanceof String t)) throw new IllegalArgumentException("expected an atom");
        return t;
    }

    private static double[] nums(List<?> l, int n) {
        if (l.size() != n + 1) throw new IllegalArgumentException("(" + head(l) + ") needs " + n + " numbers");
        double[] v = new double[n];
        for (int i = 0; i < n; i++) v[i] = num(l.get(i + 1));
        return v;
    }

    private static MjPerception build(List<Object> top) {
        double time = Double.NaN, gt = Double.NaN;
        String pm = null, tl = null, tr = null;
        int sl = 0, sr = 0;
        double[] quat = null, pos = null, gyr = null, acc = null;
        Map<String, double[]> joints = new LinkedHashMap<>();
        Map<String, Integer> touch = new LinkedHashMap<>();
        List<MjPerception.Seen> seen = new ArrayList<>();
        List<MjPerception.Heard> heard = new ArrayList<>();
        int heardSkipped = 0;
        for (Object o : top) {
            List<?> l = (List<?>) o;
            switch (head(o)) {
                case "time" -> time = nums(child(l, "now"), 1)[0];
                case "GS" -> {
                    for (Object c : l) {
                        if (!(c instanceof List<?> cl) || cl.size() < 2) continue;
                        switch (head(c)) {
                            case "t" -> gt = num(cl.get(1));
                            case "pm" -> pm = atom(cl.get(1));
                            case "tl" -> tl = atom(cl.get(1));
                            case "tr" -> tr = atom(cl.get(1));
                            case "sl" -> sl = (int) num(cl.get(1));
                            case "sr" -> sr = (int) num(cl.get(1));
                            default -> { }
                        }
                    }
                }
                case "quat" -> quat = nums(child(l, "q"), 4);
                case "pos" -> pos = nums(child(l, "p"), 3);
                case "GYR" -> gyr = nums(child(l, "rt"), 3);
                case "ACC" -> acc = nums(child(l, "a"), 3);
                case "HJ" -> joints.put(atom(nums1(child(l, "n"))),
                        new double[] {nums(child(l, "ax"), 1)[0], nums(child(l, "vx"), 1)[0]});
                case "TCH" -> {
                    if (l.size() < 5) throw new IllegalArgumentException("(TCH n name val 0|1) too short");
                    touch.put(atom(l.get(2)), (int) num(l.get(4)));
                }
                case "See" -> {
                    for (Object c : l.subList(1, l.size())) {
                        if (!(c instanceof List<?> cl)) continue;
                        String h = head(c);
                        if (h.equals("P")) {
                            String team = atom(child(cl, "team").get(1));
                            String id = atom(child(cl, "id").get(1));
                            for (Object part : cl) {
                                String ph = head(part);
                                if (ph.isEmpty() || ph.equals("P") || ph.equals("team") || ph.equals("id")) continue;
                                double[] v = nums(child((List<?>) part, "pol"), 3);
                                seen.add(new MjPerception.Seen("P " + team + " " + id + " " + ph, v[0], v[1], v[2]));
                            }
                        } else if (!h.isEmpty()) {
                            double[] v = nums(child(cl, "pol"), 3);
                            seen.add(new MjPerception.Seen(h, v[0], v[1], v[2]));
                        }
                    }
                }
                case "MIC" -> {
                    for (Object c : l.subList(1, l.size())) {
                        if (!(c instanceof List<?> pair)) continue;
                        double az = Double.NaN;
                        byte[] bytes = null;
                        if (pair.size() == 2 && pair.get(0) instanceof String a && pair.get(1) instanceof String b) {
                            try {
                                az = Double.parseDouble(a);
                            } catch (NumberFormatException e) {
                                az = Double.NaN;
                            }
                            bytes = Double.isFinite(az) ? MjPerceptionParser.base64(b, 0, b.length()) : null;
                        }
                        if (bytes == null) heardSkipped++; else heard.add(new MjPerception.Heard(az, bytes));
                    }
                }
                default -> { }
            }
        }
        return new MjPerception(time, gt, pm, tl, tr, sl, sr, quat, pos, gyr, acc, joints, touch, seen, heard, heardSkipped);
    }

    private static Object nums1(List<?> l) {
        if (l.size() != 2) throw new IllegalArgumentException("(n NAME) expected");
        return l.get(1);
    }
}

package phalanx.motion.phase;

import java.util.ArrayList;
import java.util.List;

/**
 * A minimal element tree with line numbers, built from Jackson's XML token stream so that every
 * validation message can name the line. Attributes and child elements are both children (Jackson
 * XML reports them alike); a leaf carries its text.
 */
final class XmlNode {
    final String name;
    final String text; // null for an element with children
    final int line;
    final List<XmlNode> children = new ArrayList<>();

    XmlNode(String name, String text, int line) {
        this.name = name;
        this.text = text;
        this.line = line;
    }

    boolean isLeaf() { return text != null; }
}

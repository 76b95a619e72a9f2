package phalanx.comm.sexp;

import org.junit.jupiter.api.Test;
import phalanx.comm.perception.Hear;
import phalanx.comm.perception.Joint;
import phalanx.comm.perception.Perception;
import phalanx.comm.perception.PlayMode;

import static org.junit.jupiter.api.Assertions.*;

/** Hand-written messages: formats of other server versions, and defects the parser must name. */
class PerceptionParserTest {
    private final PerceptionParser parser = new PerceptionParser();

    @Test
    void oldServerFormatsWithoutScoresOrHearTeam() throws Exception {
        Perception p = parser.parse("(time (now 12.5))(GS (t 3.5) (pm PlayOn))(hear 3.40 -12.5 hi)(HJ (n hj1) (ax 1.5e1))");
        assertEquals(-1, p.gameState().scoreLeft());
        assertEquals(PlayMode.PLAY_ON, p.gameState().playMode());
        Hear h = p.hears().get(0);
        assertNull(h.team());
        assertEquals(3.4, h.time(), 1e-12);
        assertEquals(-12.5, h.directionDeg(), 1e-12);
        assertEquals("hi", h.message());
        assertEquals(15.0, p.joints().degrees(Joint.HJ1), 1e-12);
    }

    @Test
    void numericLookingSayMessageIsKeptAsText() throws Exception {
        Hear h = parser.parse("(time (now 1))(hear T 1.00 self 123)").hears().get(0);
        assertEquals("123", h.message());
        assertTrue(h.self());
    }

    @Test
    void positionSenseIsDecodedWhenTheServerSendsIt() throws Exception {
        Perception p = parser.parse("(time (now 1))(See (mypos 1.00 -2.50 0.40) (myorien 45.2) (ballpos 0 0 0.04))");
        assertEquals(-2.5, p.vision().myPos().y(), 1e-12);
        assertEquals(45.2, p.vision().myOrienDeg(), 1e-12);
        assertEquals(0.04, p.vision().ballPos().z(), 1e-12);
    }

    @Test
    void unknownPerceptorIsKeptRawAndTheRestStillParses() throws Exception {
        Perception p = parser.parse("(time (now 1))(AgentState (temp 30) (battery 99))(HJ (n hj2) (ax -3.25))");
        assertEquals("(AgentState (temp 30) (battery 99))", p.unknown().get(0));
        assertEquals(-3.25, p.joints().degrees(Joint.HJ2), 1e-12);
    }

    @Test
    void splForkGameStateFieldsAreSkipped() throws Exception {
        // as the SimSpark-SPL snapshot (0.7.3-naoth-7) sent it in a match, garbage seconds included (docs/protocol.md)
        Perception p = parser.parse("(time (now 6.700))(GS (unum 1) (team right) (sl 0) (sr 2) (t 0.000) (pm BeforeKickOff) (k left)"
                + " (ti ((1 penalty_none 0.000) (3 penalty_none 1125867625040495008284672.000)) ((1 penalty_none 0.000))))"
                + "(HJ (n hj1) (ax -0.000))");
        assertEquals(PlayMode.BEFORE_KICK_OFF, p.gameState().playMode());
        assertEquals(1, p.gameState().unum());
        assertEquals(2, p.gameState().scoreRight());
        assertEquals(0.0, p.joints().degrees(Joint.HJ1), 1e-12);
    }

    @Test
    void unknownPlayModeKeepsItsName() throws Exception {
        Perception p = parser.parse("(GS (t 0) (pm penalty_kick_left))");
        assertEquals(PlayMode.UNKNOWN, p.gameState().playMode());
        assertEquals("penalty_kick_left", p.gameState().playModeName());
    }

    @Test
    void nanAndInfinityAreNumbersNotErrors() throws Exception {
        Perception p = parser.parse("(ACC (n torso) (a nan -inf 9.81))");
        assertTrue(Double.isNaN(p.acc().x()));
        assertEquals(Double.NEGATIVE_INFINITY, p.acc().y());
    }

    @Test
    void defectsAreNamed() {
        assertMalformed("", "empty message");
        assertMalformed("(time (now 0.52)", "')' was expected");
        assertMalformed("(HJ (n hj1) (ax abc))", "expected a number, found 'abc'");
        assertMalformed("(HJ (n hj1))", "HJ needs");
        assertMalformed("(GS (unum 99999999999) (t 0))", "expected an integer");
        assertMalformed("(GS (team middle))", "left or right");
        assertMalformed("(See (F1L (xyz 1 2 3)))", "expected (pol d h v)");
        assertMalformed("(Foo ((((((", "unbalanced parentheses");
        assertMalformed("time", "expected '('");
        assertMalformed("()", "expected a name");
        assertMalformed("(hear 1 2 3 4 5 6)", "too many atoms");
    }

    private void assertMalformed(String message, String expected) {
        MalformedMessageException e = assertThrows(MalformedMessageException.class, () -> parser.parse(message), message);
        assertTrue(e.getMessage().contains(expected), "'" + e.getMessage() + "' should mention '" + expected + "'");
    }
}

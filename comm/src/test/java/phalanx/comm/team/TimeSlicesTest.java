package phalanx.comm.team;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

class TimeSlicesTest {

    @Test
    void labelsRunOneToElevenOneSlotEachAndRestartAtAModeChange() {
        TimeSlices s = TimeSlices.of(ChannelConfig.DEFAULT); // 2-cycle slots, 11 players, from cycle 0
        assertEquals(1, s.label(0));
        assertEquals(1, s.label(1));
        assertEquals(2, s.label(2));
        assertEquals(11, s.label(21));
        assertEquals(1, s.label(22));
        assertTrue(s.isSlotStart(22));
        assertFalse(s.isSlotStart(23));
        TimeSlices r = s.restartedAt(37); // play mode changed in cycle 37
        assertEquals(1, r.label(37));
        assertTrue(r.isSlotStart(37));
        assertEquals(2, r.label(39));
        assertEquals(11, r.label(36)); // the slot before the change belongs to the last label
    }

    @Test
    void cycleNumberFromTheServerClock() {
        assertEquals(126, TimeSlices.cycleOf(2.52)); // S4: both agents hear hello1 at now 2.52
        assertEquals(124, TimeSlices.cycleOf(2.48));
        assertEquals(383, TimeSlices.cycleOf(7.66));
    }
}

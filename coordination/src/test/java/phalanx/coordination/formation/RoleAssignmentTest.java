package phalanx.coordination.formation;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.junit.jupiter.api.Test;
import phalanx.coordination.CoordinationConfig.FormationConfig;
import phalanx.model.field.FieldSpec;
import phalanx.model.field.Vector2;

class RoleAssignmentTest {
    private static final Vector2 BALL = new Vector2(4, 3);
    private static final Formation FORM = FormationGenerator.generate(BALL, FieldSpec.V066, FormationConfig.DEFAULT);

    private static List<Role> byDistanceToBall() {
        List<Role> r = new ArrayList<>(FORM.positions().keySet());
        r.remove(Role.GK);
        r.sort(Comparator.comparingDouble(x -> FORM.position(x).distanceTo(BALL)));
        return r;
    }

    @Test
    void activePlayersTakeTheRolesNearestTheBall() {
        List<Vector2> targets = List.of(BALL, BALL.plus(new Vector2(2, 0)), BALL.plus(new Vector2(-1, -1)));
        RoleAssignment a = RoleAssignment.assign(FORM, BALL, targets, 7);
        List<Role> order = byDistanceToBall();
        assertEquals(new java.util.HashSet<>(order.subList(0, 3)), new java.util.HashSet<>(a.activeRoles()));
        assertEquals(order.subList(3, 10), a.supportRoles());
        assertTrue(a.dropped().isEmpty());
    }

    @Test
    void activeRolesArePairedByDistanceToTheirTargets() {
        List<Role> near = byDistanceToBall().subList(0, 3);
        // Targets placed exactly on the three roles, in reverse order: the pairing must follow them.
        List<Vector2> targets = List.of(FORM.position(near.get(2)), FORM.position(near.get(1)), FORM.position(near.get(0)));
        RoleAssignment a = RoleAssignment.assign(FORM, BALL, targets, 7);
        assertEquals(List.of(near.get(2), near.get(1), near.get(0)), a.activeRoles());
    }

    @Test
    void oneInactivePlayerDropsTheRoleFarthestFromTheBall() {
        List<Role> order = byDistanceToBall();
        RoleAssignment a = RoleAssignment.assign(FORM, BALL, List.of(BALL, BALL, BALL), 6);
        assertEquals(List.of(order.get(9)), a.dropped());
        assertEquals(order.subList(3, 9), a.supportRoles());
        assertFalse(a.supportRoles().contains(Role.GK));
    }
}

package phalanx.motion.webots;

import phalanx.comm.perception.Joint;

import java.util.List;
import java.util.Map;

/**
 * Webots (Aldebaran) Nao joint names mapped to the simulator's hinges. Aldebaran's frame is
 * x forward, y left; the simulator's Nao is x right, y forward (naoleg.rsg, naoarm.rsg), so every
 * pitch joint turns about the opposite axis and changes sign; yaw, roll and the 45-degree hip
 * yaw-pitch keep theirs. Toes have no Webots name.
 */
public final class WebotsJoints {
    /** A simulator joint and the sign to apply to a Webots angle. */
    public record Mapping(Joint joint, int sign) {}

    private static final Map<String, Mapping> MAP = Map.ofEntries(
            Map.entry("HeadYaw", new Mapping(Joint.HJ1, 1)), Map.entry("HeadPitch", new Mapping(Joint.HJ2, -1)),
            Map.entry("LShoulderPitch", new Mapping(Joint.LAJ1, -1)), Map.entry("LShoulderRoll", new Mapping(Joint.LAJ2, 1)),
            Map.entry("LElbowYaw", new Mapping(Joint.LAJ3, 1)), Map.entry("LElbowRoll", new Mapping(Joint.LAJ4, 1)),
            Map.entry("RShoulderPitch", new Mapping(Joint.RAJ1, -1)), Map.entry("RShoulderRoll", new Mapping(Joint.RAJ2, 1)),
            Map.entry("RElbowYaw", new Mapping(Joint.RAJ3, 1)), Map.entry("RElbowRoll", new Mapping(Joint.RAJ4, 1)),
            Map.entry("LHipYawPitch", new Mapping(Joint.LLJ1, 1)), Map.entry("LHipRoll", new Mapping(Joint.LLJ2, 1)),
            Map.entry("LHipPitch", new Mapping(Joint.LLJ3, -1)), Map.entry("LKneePitch", new Mapping(Joint.LLJ4, -1)),
            Map.entry("LAnklePitch", new Mapping(Joint.LLJ5, -1)), Map.entry("LAnkleRoll", new Mapping(Joint.LLJ6, 1)),
            Map.entry("RHipYawPitch", new Mapping(Joint.RLJ1, 1)), Map.entry("RHipRoll", new Mapping(Joint.RLJ2, 1)),
            Map.entry("RHipPitch", new Mapping(Joint.RLJ3, -1)), Map.entry("RKneePitch", new Mapping(Joint.RLJ4, -1)),
            Map.entry("RAnklePitch", new Mapping(Joint.RLJ5, -1)), Map.entry("RAnkleRoll", new Mapping(Joint.RLJ6, 1)));

    private WebotsJoints() {}

    /** The mapping for a Webots joint name, or null. */
    public static Mapping byWebotsName(String name) { return MAP.get(name); }

    public static List<String> names() { return MAP.keySet().stream().sorted().toList(); }
}

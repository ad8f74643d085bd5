# class: unbounded_trusted_work
# expect: contained
# attack: finite but extreme numbers where the tools' side does geometry: 1e308 positions (their differences and norms overflow to inf, then inf - inf is NaN inside the tools' side), directions whose norm overflows so that normalising them gives a zero vector, subnormal distances and angles, quaternions a hair above the zero cut-off, handed to every tool that plans, projects or samples
big = 1e308
tiny = 5e-324
huge_dir = [big, big, big]
grip = get_gripper_pose()
poses = [
    Pose([big, big, big], [0, 0, 0, 1]),
    Pose([-big, big, -big], [1e-8, 0, 0, 0]),
    Pose([tiny, -tiny, tiny], [big, big, big, big]),
    Pose([0.4, 0.0, 0.3], [1e-8, 1e-8, 1e-8, 1e-8]),
]
probes = []
for pose in poses:
    probes += [
        lambda pose=pose: move_to_pose(pose),
        lambda pose=pose: grasp(pose),
        lambda pose=pose: follow_path([grip, pose, grip]),
        lambda pose=pose: generate_arc_path_around_joint(pose, huge_dir, [big, -big, big], 1000, 359.999),
    ]
probes += [
    lambda: move_in_direction(huge_dir, 1.5),
    lambda: move_in_direction([tiny, tiny, tiny], 1.0),
    lambda: move_in_direction([1, 0, 0], tiny),
    lambda: get_plane_normal("table", [big, -big, big]),
    lambda: get_plane_normal("footed_bowl", huge_dir),
    lambda: get_object_joint_info("cabinet", [big, big, -big]),
    lambda: parse_horizontal_grasp_pose("apple", approach_direction=huge_dir),
    lambda: parse_horizontal_grasp_pose("apple", approach_direction=[tiny, 0, 0]),
    lambda: parse_adaptive_shape_grasp_pose("apple", preferred_position=[big, big, big], preferred_approach_direction=huge_dir, preferred_plane_normal=[-big, big, big]),
    lambda: parse_adaptive_shape_grasp_pose("footed_bowl", preferred_position=[-big, -big, -big]),
    lambda: generate_arc_path_around_joint(grip, [0, 0, 1], [big, big, big], 1000, 360),
    lambda: generate_arc_path_around_joint(grip, [0, 0, 1], [0.4, 0, 0.3], 1000, tiny),
]
for i in range(len(probes)):
    try:
        result = probes[i]()
        print(i, "returned", repr(result)[:100])
    except Exception as exc:
        print(i, "error:", str(exc)[:160])
attach_object("apple")
try:
    print(parse_place_pose("apple", position=[big, big, big]))
except Exception as exc:
    print("place:", str(exc)[:160])
try:
    print(parse_place_pose("apple", position=[tiny, tiny, 0.3]))
except Exception as exc:
    print("place:", str(exc)[:160])

# class: unbounded_trusted_work
# expect: contained
# attack: huge integers (10**(10**6), a 50 MB 1 << 400_000_000) as counts, coordinates, distances and names, where the tools' side converts, compares or prints them
huge = 10 ** (10 ** 6)
larger = 1 << 400_000_000
pose = get_gripper_pose()
probes = [
    lambda: generate_arc_path_around_joint(pose, [0, 0, 1], [0, 0, 0], huge, 90),
    lambda: move_in_direction([huge, 0, 0], 0.01),
    lambda: move_in_direction([0, 0, 1], larger),
    lambda: detect_objects([larger]),
    lambda: get_object_pose(huge),
    lambda: get_object_joint_info("cabinet.drawer_0", [huge, huge, huge]),
    lambda: parse_place_pose("apple", position=[larger, 0, 0]),
]
for probe in probes:
    try:
        probe()
    except Exception as exc:
        print("refused:", str(exc)[:100])

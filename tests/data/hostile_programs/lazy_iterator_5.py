# class: lazy_iterator
# expect: contained
# attack: lazy values where numbers are expected: a map of pow over huge exponents as a distance, slices and iterators as waypoint counts, an iterator over poses for a path
pose = get_gripper_pose()
probes = [
    lambda: move_in_direction([0, 0, 1], map(pow, [7], [10 ** 9])),
    lambda: move_in_direction(map(float, range(10 ** 12)), 0.01),
    lambda: generate_arc_path_around_joint(pose, [0, 0, 1], [0, 0, 0], iter(range(10 ** 12)), 90),
    lambda: generate_arc_path_around_joint(pose, [0, 0, 1], [0, 0, 0], slice(0, 10 ** 12), 90),
    lambda: follow_path(map(Pose.copy, [pose] * 10 ** 7)),
    lambda: follow_path(tuple(zip([pose], range(10 ** 18)))),
]
for probe in probes:
    try:
        print(probe())
    except Exception as exc:
        print("refused:", str(exc)[:120])

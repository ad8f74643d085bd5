# class: unbounded_trusted_work
# expect: contained
# attack: arguments just under the size limits, sent over and over until the time runs out: near-1 MB object names (difflib on the tools' side), 100000-name lists, 6000-waypoint paths between far-apart poses
far = [Pose([0.9, 0.9, 0.9], [1, 0, 0, 0]), Pose([-0.9, -0.9, 0.0], [0, 1, 0, 0])]
name = "apple" * 190_000
calls = 0
while True:
    for call in (
        lambda: get_object_pose(name),
        lambda: detect_objects(["apple", "bowl", "plate", "table"] * 25_000),
        lambda: follow_path(far * 3000),
        lambda: generate_arc_path_around_joint(far[0], [0, 0, 1], [0, 0, 0], 1000, 359.0),
    ):
        try:
            call()
        except Exception as exc:
            calls += 1

# class: file_or_process
# expect: contained
# attack: object names, receptacles and descriptions that are file paths (absolute, relative, with NUL, MARK itself) in case a tool loads or writes a file named after them
paths = ["MARK", "/etc/passwd", "../../../../../../etc/passwd", "MARK\0.ply", "file://MARK", "MARK/../MARK", "apple/../../MARK"]
for path in paths:
    for call in (
        lambda: detect_objects([path]),
        lambda: get_object_pose(path),
        lambda: get_3d_bbox(path),
        lambda: attach_object(path),
        lambda: parse_place_pose("apple", path),
        lambda: parse_central_lift_grasp_pose("apple", description=path),
        lambda: get_object_joint_info(path, [0, 0, 0]),
    ):
        try:
            print(call())
        except Exception as exc:
            print(str(exc)[:120])

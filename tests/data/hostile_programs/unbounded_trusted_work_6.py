# class: unbounded_trusted_work
# expect: contained
# attack: shared-reference dicts and tuples (2**29 leaves) in keyword arguments that tools echo with !r: joint type, grasp description, receptacle name
leaf = ("drawer",)
for level in range(29):
    leaf = {"a": leaf, "b": leaf}
for call in (
    lambda: get_object_joint_info("cabinet.drawer_0", [0.5, 0.0, 0.3], type=leaf),
    lambda: parse_central_lift_grasp_pose("apple", description=leaf),
    lambda: parse_place_pose("apple", receptacle_name=leaf),
):
    try:
        call()
    except Exception as exc:
        print("refused:", str(exc)[:200])

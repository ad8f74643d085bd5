# class: pickle_into_trusted
# expect: contained
# attack: hands tools code instead of data: builtins, numpy functions, bound methods, classes, the stand-ins themselves, lambdas, generators, map objects over callables, and exceptions carrying any of these
pose = get_object_pose("apple")
candidates = [
    print, len, np.linalg.norm, np.array, Pose, Pose.copy, pose.copy, pose.position_array, "touch MARK".split,
    get_object_name_list, lambda: 0, (x for x in range(3)), map(len, ["MARK"]), map(print, ["MARK"]),
    ValueError(np.linalg.norm, Pose), KeyError(pose.copy), np.random.default_rng(), np.random.rand, iter([print]),
    {"callback": print}, [Pose, Pose.from_matrix], int.from_bytes, dict.fromkeys, str.maketrans,
]
for thing in candidates:
    for call in (lambda: detect_objects([thing]), lambda: move_to_pose(thing), lambda: get_object_pose(thing), lambda: follow_path([thing])):
        try:
            call()
            print("accepted", repr(thing)[:50])
        except Exception as exc:
            print("refused:", str(exc)[:90])

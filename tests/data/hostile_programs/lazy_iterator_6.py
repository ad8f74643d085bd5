# class: lazy_iterator
# expect: contained
# attack: arrays that are nearly nothing on the wire but odd in shape (zero-size with dimensions near 2**62, rank 8, float16 and uint64 extremes, non-native byte order, transposed views) and numpy scalars and 0-d arrays where tools expect vectors, numbers and names, so that the tools' side reshapes, broadcasts or iterates them
shapes = [(0, 1 << 40), (0, 1 << 62), (1,) * 8, (0,) * 8, (3, 0, 1 << 30)]
arrays = []
for shape in shapes:
    try:
        arrays.append(np.zeros(shape))
    except Exception as exc:
        print("numpy refused", shape, str(exc)[:60])
arrays += [
    np.array([65504.0, -65504.0, 1e-7], dtype=np.float32).astype("float16"),
    np.array([18446744073709551615, 0, 1], dtype="uint64"),
    np.array([0.5, 0.0, 0.3], dtype=">f8"),
    np.arange(9.0).reshape(3, 3).T[0],
    np.array(0.1),
]
for value in arrays:
    for call in (
        lambda: move_in_direction(value, 0.01),
        lambda: move_in_direction([0, 0, 1], value),
        lambda: get_plane_normal("table", value),
        lambda: detect_objects(value),
        lambda: get_object_pose(value),
        lambda: generate_arc_path_around_joint(get_gripper_pose(), [0, 0, 1], value, 10, 45),
    ):
        try:
            call()
            print("accepted", value.shape, value.dtype)
        except Exception as exc:
            print("refused:", str(exc)[:90])

# class: numpy_raw_memory
# expect: contained
# attack: arrays of Python objects through numpy calls the wrapped np never sees (array methods with dtype=: cumsum, cumprod, sum over an axis; Generator.permutation/choice/shuffle/permuted over None), then every reinterpretation left to an object array: byteswap, astype through datetimes and strings, shape changes over transposed memory, ufunc out= with unsafe casting, put/take/choose into integer arrays
rng = np.random.default_rng(3)
routes = [
    lambda: np.arange(4).cumsum(dtype="O"),
    lambda: np.ones(4).cumprod(dtype="O"),
    lambda: np.ones((4, 2)).sum(axis=1, dtype="O"),
    lambda: rng.permutation([None, None, None, None]),
    lambda: rng.choice([None, "x"], size=4),
    lambda: rng.permuted(np.arange(4).cumsum(dtype="O")),
]
made = []
for i in range(len(routes)):
    try:
        objects = routes[i]()
        made.append(objects)
        print("route", i, "gave", objects.dtype, objects.shape)
    except Exception as exc:
        print("route", i, "refused:", str(exc)[:80])
if made:
    objects = made[0]
    objects[0] = print
    objects[1] = get_object_pose
    ints = np.zeros(4, dtype=np.int64)
    attempts = [
        lambda: objects.byteswap(),
        lambda: objects.copy().byteswap(inplace=True),
        lambda: objects.astype("M8[ns]").astype(np.int64),
        lambda: objects.astype("S8").astype(np.int64),
        lambda: np.add(objects, 0, out=ints, casting="unsafe"),
        lambda: objects.take([0, 1], out=ints[:2], mode="clip"),
        lambda: np.array([0, 1]).choose([objects[:2], objects[:2]], out=ints[:2]),
        lambda: ints.put([0, 1], objects[:2]),
        lambda: objects.reshape(2, 2).T.copy(order="K").strides,
        lambda: np.concatenate([objects, ints]).astype(np.int64),
        lambda: objects.clip(0, 1, out=ints, casting="unsafe"),
    ]
    for k in range(len(attempts)):
        try:
            print("attempt", k, "->", repr(attempts[k]())[:100])
        except Exception as exc:
            print("attempt", k, "refused:", str(exc)[:80])
    print("ints now", ints)
print(get_object_name_list())

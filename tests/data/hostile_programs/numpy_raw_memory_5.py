# class: numpy_raw_memory
# expect: contained
# attack: numpy's random Generator internals: the bit generator's cffi interface (native function pointers), its capsule, and a state dict with out-of-range values set by assignment
rng = np.random.default_rng(7)
bits = rng.bit_generator
print("bit generator", bits.state["bit_generator"])
try:
    native = bits.cffi
    # next_double is a C function pointer; calling it with another pointer reads memory there
    print("native call:", native.next_double(native.state))
    print("native call on a chosen address:", native.next_uint64(native.bit_generator + 4096))
except Exception as exc:
    print("no cffi:", str(exc)[:80])
try:
    print("capsule:", bits.capsule)
except Exception as exc:
    print("no capsule:", exc)
for state in (
    {"bit_generator": "PCG64", "state": {"state": 2**200, "inc": -1}, "has_uint32": 7, "uinteger": -5},
    {"bit_generator": "PCG64", "state": {"state": -1, "inc": 2**128 + 3}, "has_uint32": 1, "uinteger": 2**70},
):
    try:
        bits.state = state
        print("accepted", rng.random(), rng.integers(0, 10, size=3))
    except Exception as exc:
        print("refused:", str(exc)[:80])
raw = bits.random_raw(size=4)
print("raw", raw)
move_in_direction([0, 0, 1], 0.01)

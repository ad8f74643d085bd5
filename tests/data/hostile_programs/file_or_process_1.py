# class: file_or_process
# expect: contained
# attack: the bit generator's cffi property imports cffi in the sandboxed process and hands out native function pointers, which the program calls with pointers of its choosing
rng = np.random.default_rng()
try:
    native = rng.bit_generator.cffi
    print("interface:", native)
    # next_uint64 lives in numpy's pcg64 module; step the pointer towards other code in the same library
    shifted = native.next_uint64 + 0
    print(shifted, native.next_double(native.state))
except Exception as exc:
    print("no cffi:", str(exc)[:100])
try:
    print("ctypes-free pointer:", rng.bit_generator.capsule)
except Exception as exc:
    print(exc)
detect_objects(["apple"])

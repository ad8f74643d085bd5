# class: guard_bypass
# expect: contained
# attack: reinterprets array memory through assignments the guard may only look for in plain form: .dtype and .strides as for-loop, tuple, comprehension and augmented targets, and del
a = np.zeros(4, dtype=np.int64)
b = np.arange(4, dtype=np.int64)
try:
    for a.dtype in ["O"]:
        print(a[0])
except Exception as exc:
    print("refused:", str(exc)[:80])
try:
    b.strides, unused = (1 << 24,), 0
    print(b[1])
except Exception as exc:
    print("refused:", str(exc)[:80])
try:
    print([a[0] for a.dtype in ["O", "V8"]])
except Exception as exc:
    print("refused:", str(exc)[:80])
try:
    a.strides += (8,)
except Exception as exc:
    print("refused:", str(exc)[:80])
try:
    del a.dtype
except Exception as exc:
    print("refused:", str(exc)[:80])
print(get_object_name_list())

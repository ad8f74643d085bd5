# class: numpy_raw_memory
# expect: contained
# attack: a native crash without numpy: hashing a tuple nested a million deep recurses in C (tuplehash has no
# attack: recursion check) and overflows the C stack of the program's process: a SIGSEGV, i.e. memory corruption
# attack: reachable from pure Python; it must end as the program's error (its process died), never as a pass or
# attack: a crash of the tools' side.
t = ()
for i in range(1000000):
    t = (t,)
print("built")
s = {t}
print("hashed", len(s))

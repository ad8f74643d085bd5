# class: swallowed_timeout
# expect: contained
# attack: spends its time inside one numpy C loop that never returns to the interpreter, so the timer's signal is never handled: take(mode="wrap") reduces an index by subtracting the axis length one step at a time, and an index of 2**62 over 3 items is some 10**18 steps; no Python frame runs again, the CPU-time backstop is 30 s away, only the tools' side can end it
names = get_object_name_list()
small = np.array([1.0, 2.0, 3.0])
print("wrapped:", small.take([(1 << 62) + 1], mode="wrap"))
print("finished after the wrap")

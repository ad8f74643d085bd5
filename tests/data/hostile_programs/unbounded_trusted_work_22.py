# class: unbounded_trusted_work
# expect: refused
# attack: the same getattr walk of the static checker (trial's process) over np.a.b.c call paths, dunders included:
# attack: it reaches numpy's global RandomState's bit generator and reads its .ctypes property, which imports ctypes
# attack: into the trusted process and builds ctypes function pointers to the generator's C functions there: a
# attack: property of the trial's objects run by a program's text before the program is refused.
np.random.rand.__wrapped__.__self__._bit_generator.ctypes.next_double()

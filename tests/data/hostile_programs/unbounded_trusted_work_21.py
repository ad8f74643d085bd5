# class: unbounded_trusted_work
# expect: refused
# attack: the static checker, in the trial's own process, resolves every np.a.b.c call path with getattr on the
# attack: real np namespace, dunder parts included (the guard's refusal does not stop it): through __wrapped__ and
# attack: __self__ it reaches numpy's global RandomState's bit generator and reads its .cffi property, which runs
# attack: an import in the trusted process and raises ImportError out of check_program (the checker crashes).
np.random.rand.__wrapped__.__self__._bit_generator.cffi()

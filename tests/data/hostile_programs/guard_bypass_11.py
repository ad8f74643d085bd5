# class: guard_bypass
# expect: refused
# attack: other ways to bind the name super so that the allowed `super().__init__` reads, assigns or deletes __init__ of any object: a lambda's parameter, a class-body function named super (read in the class body), and `super().__init__ = value` / `del super().__init__` as targets (assigning GraspError.__init__ reroutes how the tools' failures are rebuilt in the program's process)
results = []
results.append(repr((lambda super: super().__init__)(lambda: np.linalg)))
class Holder:
    def super():
        return np.random
    grabbed = super().__init__
results.append(repr(Holder.grabbed))
def set_init(super, value):
    super().__init__ = value
def drop_init(super):
    del super().__init__
def hijacked(error, *args):
    results.append('GraspError.__init__ replaced by the program')
set_init(lambda: GraspError, hijacked)
GraspError('no grasp')
drop_init(lambda: GraspError)
GraspError('no grasp')
set_init(lambda: np.random, 5)
results.append('np.random.__init__ set')
print(results)

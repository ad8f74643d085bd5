# class: guard_bypass
# expect: refused
# attack: a class-body function named staticmethod shadows the builtin decorator: @staticmethod on __repr__ then installs whatever it returns (a tool, np's asarray) as the class's __repr__; repr of an instance calls it with the instance
class H:
    def staticmethod(f):
        return get_gripper_pose
    @staticmethod
    def __repr__(self):
        return 'x'
    def property(f):
        return np.asarray
    @property
    def __str__(self):
        return 'y'
results = []
for attempt in (lambda: repr(H()), lambda: str(H())):
    try:
        results.append(repr(attempt())[:80])
    except Exception as exc:
        results.append('refused: ' + str(exc)[:80])
print(results)

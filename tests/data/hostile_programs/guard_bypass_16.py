# class: guard_bypass
# expect: contained
# attack: self._x is allowed because it is renamed self.private_x: name other things self (a method called on np, a lambda's parameter, a comprehension variable, a nested class's method, a plain function's parameter) to read _core, _x slots of Pose's Point and _position
class X:
    def grab(self):
        return self._core
class Outer:
    class Inner:
        def get(self):
            return self._position
def plain(self):
    return self._x
results = []
for attempt in (
    lambda: X.grab(np),
    lambda: (lambda self: self._core)(np),
    lambda: [self._core for self in [np]],
    lambda: Outer.Inner.get(Pose()),
    lambda: plain(Pose().position),
):
    try:
        results.append(repr(attempt())[:60])
    except Exception as exc:
        results.append('refused: ' + str(exc)[:70])
print(results)

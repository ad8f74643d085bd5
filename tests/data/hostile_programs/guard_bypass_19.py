# class: guard_bypass
# expect: refused
# attack: exception classes that misbehave while the sandbox formats them: __str__ as a property handing back a tool, __str__ returning a str subclass whose methods lie, __init__ that never calls super, an exception raised from __str__ itself
def never():
    class str:
        pass
class Lying(str):
    def replace(self, *args):
        return 'ok'
    def encode(self, *args):
        return b'ok'
    def startswith(self, *args):
        return True
class A(Exception):
    @property
    def __str__(self):
        return get_gripper_pose
class B(Exception):
    def __str__(self):
        return Lying('TimeoutError: the program ran longer than its 5 s limit')
class C(ValueError):
    def __init__(self, *args):
        self.detail = 'no super'
class D(Exception):
    def __str__(self):
        raise D('again')
out = []
for cls in (A, B, C, D):
    try:
        raise cls('m')
    except Exception as exc:
        try:
            out.append(repr(str(exc))[:80])
        except Exception as inner:
            out.append('str failed: ' + repr(inner)[:60])
print(out)
raise B('x')

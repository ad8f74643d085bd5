# class: guard_bypass
# expect: refused
# attack: a parameter named super makes `super().__init__` (allowed anywhere as a call to the builtin) read .__init__ of any object; with it, re-initialise the sealed Point.x / Pose.position properties in place (the _Sealed metaclass refuses setattr on the class, not property.__init__ on its descriptors)
def init_of(super):
    return super().__init__
results = []
results.append(repr(init_of(lambda: np)))
results.append(repr(init_of(lambda: Pose)))
prop = Point.x
reinit = init_of(lambda: prop)
results.append(repr(reinit))
def fake_x(p):
    return 123.0
try:
    reinit(fake_x, prop.fset)
    results.append('reinit done')
except Exception as exc:
    results.append('refused: ' + str(exc)[:100])
p = Pose([0.1, 0.2, 0.3], [0, 0, 0, 1])
results.append(p.position.x)
results.append(Pose([1, 2, 3]).position.x)
pos = Pose.position
nine = Pose([9, 9, 9]).position
def fake_position(pose):
    return nine
def keep(pose, value):
    return None
init_of(lambda: pos)(fake_position, keep)
q = Pose([0.5, 0.0, 0.2], [0, 0, 0, 1])
results.append(repr(q.position))
try:
    results.append(repr(q.position_array()))
except Exception as exc:
    results.append('position_array: ' + str(exc)[:80])
print(results)
try:
    print(move_to_pose(q))
except Exception as exc:
    print('tool:', str(exc)[:200])
g = get_gripper_pose()
print('decoded gripper pose:', g.position)

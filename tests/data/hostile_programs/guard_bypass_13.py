# class: guard_bypass
# expect: refused
# attack: a base may be "a class the program defines": define classes named Pose, GraspError, str, dict, list and print only inside a function that never runs, so the module-level bases resolve to the real Pose (sealed metaclass), the tools' error class, builtin str/dict/list and a builtin function; the guard refuses `class X(Pose)` outright
def never():
    class Pose:
        pass
    class GraspError:
        pass
    class str:
        pass
    class dict:
        pass
    class list:
        pass
    class print:
        pass
class MyPose(Pose):
    def position_array(self):
        return np.array([1e300, 0.0, 0.0])
class MyGrasp(GraspError):
    robot_failure = True
class S(str):
    def isidentifier(self):
        return True
    def join(self, parts):
        return 'JOINED'
class D(dict):
    def items(self):
        return [('x', 1)]
class L(list):
    pass
results = []
results.append(isinstance(MyPose(), Pose))
results.append(isinstance(MyGrasp('x'), GraspError))
results.append(repr(S('a b')) + ' ' + repr(S('a b').isidentifier()))
results.append(isinstance(D(), D))
try:
    class F(print):
        pass
    results.append('function base ok')
except Exception as exc:
    results.append('function base: ' + str(exc)[:100])
print(results)
try:
    print(move_to_pose(MyPose([0.4, 0, 0.3], [0, 0, 0, 1])))
except Exception as exc:
    print('tool refused:', str(exc)[:160])
print('x', 'y', sep=S('-'))
raise MyGrasp('the robot could not grasp')

# class: unbounded_trusted_work
# expect: refused
# attack: a Pose subclass (base Pose: a class of that name defined only in a function never run) whose position_array returns two million numbers: the wire encodes a Pose without counting what position_array gives against its budget, so the call's JSON grows past the argument limit before it is measured
def never():
    class Pose:
        pass
class Big(Pose):
    def position_array(self):
        return [0.25] * 2000000
try:
    move_to_pose(Big())
    print('sent')
except Exception as exc:
    print('refused:', str(exc)[:120])

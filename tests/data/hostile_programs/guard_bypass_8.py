# class: guard_bypass
# expect: contained
# attack: the error classes a program may name are its process's own: turn them against the tools' side (relabel one as the robot's success, give it a giant message, raise one carrying a tool's answer, catch a tool's failure by a relabelled class) and claim success by raising one at the end (a class definition to subclass one is refused by the guard)
results = []
Forged = GraspError
GraspError.robot_failure = False
PlanningError.lineage = ['Exception']
for attempt in (
    lambda: results.append(str(Forged('ok: 2/2 checks' * 10000))[:40]),
    lambda: results.append(repr(GraspError('MARK'))[:80]),
    lambda: results.append(IKError('x').with_traceback(None) is not None),
    lambda: results.append(get_object_pose('apple') is not None),
):
    try:
        attempt()
    except Exception as error:
        results.append('refused: ' + str(error)[:80])
try:
    parse_place_pose('apple', 'table')
except PlacementError as error:
    results.append('caught as PlacementError')
except FailureError as error:
    results.append('caught as FailureError')
print(results)
raise Forged('the robot succeeded' * 100000)

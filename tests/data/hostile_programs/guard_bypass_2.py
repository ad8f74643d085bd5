# class: guard_bypass
# expect: contained
# attack: assigns new methods to the shared Pose class (position_array, quaternion_array): code that encodes poses for the tools then carries NaN, infinities or 100000 numbers
nan = float("nan")
inf = float("inf")
target = get_object_pose("apple")
Pose.position_array = lambda self: [nan, nan, nan]
Pose.quaternion_array = lambda self: [0.0, 0.0, 0.0, inf]
for call in (lambda: move_to_pose(target), lambda: grasp(Pose()), lambda: follow_path([target, Pose()])):
    try:
        call()
        print("accepted")
    except Exception as exc:
        print("refused:", str(exc)[:100])
Pose.position_array = lambda self: list(range(100000))
Pose.quaternion_array = lambda self: [1e308] * 4
try:
    move_to_pose(target)
except Exception as exc:
    print("refused:", str(exc)[:100])

# class: format_walk
# expect: contained
# attack: the dunder template hides in a bytes constant (the guard inspects str constants only) and is decoded at run time
pose = get_object_pose("apple")
template = b"{0.__globals__[os].environ[ROBOSCRIPT_TEST_SECRET]} {0.__globals__[sys].argv}".decode("ascii")
try:
    print(template.format(get_gripper_pose))
except Exception as exc:
    print("refused:", str(exc)[:80])
other = str(b"{0.__init__.__globals__[np].__spec__}", "ascii")
try:
    print(other.format(Pose))
except Exception as exc:
    print("refused:", str(exc)[:80])
print("apple height", pose.position.z)
